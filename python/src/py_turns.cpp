#include "py_turns.hpp"

#include <chrono>

#include "py_common.hpp"

namespace nck::py {

Turns::Turn Turns::take() {
  if (!busy_.try_lock()) {
    if (owner_.load() == std::this_thread::get_id())
      raise("SessionBusy", ErrorId::AppSessionBusy,
            "the session was called from inside one of its own calls (a __del__, a gc callback or a signal "
            "handler that ran meanwhile); waiting for the turn would never end");
    wait();
  }
  owner_.store(std::this_thread::get_id());
  return Turn(*this);
}

// Slices of 20 ms: short beside a human's Ctrl-C, long beside the cost of
// taking the GIL back to look for it.
void Turns::wait() {
  for (;;) {
    bool got = false;
    {
      pyb::gil_scoped_release no_gil;
      got = busy_.try_lock_for(std::chrono::milliseconds(20));
    }
    if (got) return;
    if (PyErr_CheckSignals() != 0) throw pyb::error_already_set();
  }
}

void Turns::give_back() {
  owner_.store(std::thread::id{});
  busy_.unlock();
}

}  // namespace nck::py
