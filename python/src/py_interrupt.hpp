#pragma once
// Ctrl-C while a run or a step goes on: the cycles run without the GIL, so
// Python's own SIGINT handler cannot act until they return. In the main
// thread, for the length of the call, SIGINT raises `flag` instead (the
// caller stops at the next cycle) and, once the call is over, Python's
// handler is back and the call raises KeyboardInterrupt.
#include <atomic>
#include <csignal>

namespace nck::py {

class CtrlC {
 public:
  explicit CtrlC(std::atomic<bool>& flag);  // setup, with the GIL held
  ~CtrlC();                                 // restores the handler
  CtrlC(const CtrlC&) = delete;
  CtrlC& operator=(const CtrlC&) = delete;
  // With the GIL held: KeyboardInterrupt if SIGINT came during the call.
  void raise_if_pressed() const;

 private:
  bool installed_ = false;
  struct sigaction old_{};
};

}  // namespace nck::py
