#pragma once
// What nck-hal's events and state name (prep::RunRecords) while its kernel
// runs in rtapi_app: the machine it packed, its preparation's decoder (the
// files' names) and plan store (texts, payloads, block maps), and the
// spindles' designations in the kernel's order (app::machine_spindles).
#include <string>
#include <vector>

#include "nck/output/machine_names.hpp"
#include "nck/prep/channel_prep.hpp"
#include "nck/prep/run_records.hpp"

namespace nck::hal {

class HalRecords final : public prep::RunRecords {
 public:
  HalRecords(const config::Machine& m, const prep::PlanStore& store, const prep::ChannelPrep& prep)
      : machine_(m), store_(store), prep_(prep), spindles_(app::machine_spindles(m)) {}

  const config::Machine& config() const override { return machine_; }
  // nck-hal prepares channel 1 only.
  const nc::Decoder* decoder(std::size_t ch) const override { return ch == 0 ? prep_.decoder() : nullptr; }
  const std::string* spindle_name(std::size_t index) const override {
    return index < spindles_.size() ? &spindles_[index].name : nullptr;
  }

 private:
  const prep::PlanStore& store() const override { return store_; }

  const config::Machine& machine_;
  const prep::PlanStore& store_;
  const prep::ChannelPrep& prep_;
  std::vector<app::SpindleName> spindles_;  // in the kernel's order
};

}  // namespace nck::hal
