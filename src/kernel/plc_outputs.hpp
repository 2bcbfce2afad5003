#pragma once
// The kernel's side of the technology-function handshake: numbers each
// output, hands it to the PLC through the cycle's TickOutput and counts the
// outputs not yet acknowledged, so that the PLC side never holds more than
// kMaxPendingOutputs (a bound both sides are built for).
#include <cstddef>

#include "nck/kernel/tick_io.hpp"

namespace nck::kernel {

class PlcOutputs {
 public:
  // rt: kNoHandle when kMaxPendingOutputs outputs wait for their
  // acknowledgement (the caller raises PlcOutputQueueFull).
  plc::OutputHandle submit(const plc::TechOutput& o, TickOutput& out) noexcept {
    if (outstanding_ >= kMaxPendingOutputs) return plc::kNoHandle;
    const plc::OutputHandle h = next_++;
    if (next_ == plc::kNoHandle) next_ = 1;  // wraps after 4e9 outputs
    (void)out.tech_outputs.push_back(TechRequest{h, o});  // fits: at most kMaxPendingOutputs per cycle
    ++outstanding_;
    return h;
  }
  // rt: the PLC acknowledged one output.
  void acknowledged() noexcept {
    if (outstanding_ > 0) --outstanding_;
  }

 private:
  plc::OutputHandle next_ = 1;
  std::size_t outstanding_ = 0;
};

}  // namespace nck::kernel
