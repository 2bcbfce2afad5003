#pragma once
// What nck-hal's events and state name (prep::RunRecords) while its kernel
// runs in rtapi_app: the machine it packed, its preparation's decoder (the
// files' names) and plan store (texts, payloads, block maps), and the
// spindles' designations in the kernel's order (plc::build_spindle_map).
#include <string>
#include <vector>

#include "nck/plc/hli.hpp"
#include "nck/prep/channel_prep.hpp"
#include "nck/prep/run_records.hpp"

namespace nck::hal {

class HalRecords final : public prep::RunRecords {
 public:
  HalRecords(const config::Machine& m, const prep::PlanStore& store, const prep::ChannelPrep& prep)
      : machine_(m), store_(store), prep_(prep) {
    const plc::SpindleMap map = plc::build_spindle_map(m);
    spindles_.assign(map.count, std::string());
    for (std::size_t c = 0; c < m.channels.size(); ++c)
      for (std::size_t i = 0; i < m.channels[c].spindles.size(); ++i) {
        const std::int8_t k = map.at(c + 1, static_cast<std::int32_t>(i));
        if (k >= 0 && spindles_[static_cast<std::size_t>(k)].empty())
          spindles_[static_cast<std::size_t>(k)] = m.channels[c].spindles[i].name;
      }
  }

  const config::Machine& config() const override { return machine_; }
  // nck-hal prepares channel 1 only.
  const nc::Decoder* decoder(std::size_t ch) const override { return ch == 0 ? prep_.decoder() : nullptr; }
  const std::string* spindle_name(std::size_t index) const override {
    return index < spindles_.size() ? &spindles_[index] : nullptr;
  }

 private:
  const prep::PlanStore& store() const override { return store_; }

  const config::Machine& machine_;
  const prep::PlanStore& store_;
  const prep::ChannelPrep& prep_;
  std::vector<std::string> spindles_;
};

}  // namespace nck::hal
