#pragma once
// One Python caller at a time in an object whose calls release the GIL (a
// Session: two threads stepping one Simulation corrupted memory). A caller
// that finds the object busy waits for its turn without the GIL, which the
// busy call needs back to return; it waits in slices and looks for Ctrl-C
// in between, so the main thread waiting behind a long step still gets its
// KeyboardInterrupt. A call from inside the busy call itself (the same
// thread: a __del__, a gc callback or a signal handler that ran while the
// call built its result) would wait for ever: it raises SessionBusy
// (940203) instead.
#include <atomic>
#include <mutex>
#include <thread>
#include <utility>

namespace nck::py {

class Turns {
 public:
  // The turn, given back when it goes out of scope (with the GIL held or not).
  class Turn {
   public:
    explicit Turn(Turns& t) : t_(&t) {}
    Turn(Turn&& o) noexcept : t_(std::exchange(o.t_, nullptr)) {}
    Turn(const Turn&) = delete;
    Turn& operator=(const Turn&) = delete;
    Turn& operator=(Turn&&) = delete;
    ~Turn() {
      if (t_) t_->give_back();
    }

   private:
    Turns* t_;
  };

  // With the GIL held: waits for the turn (KeyboardInterrupt on Ctrl-C,
  // SessionBusy when this thread holds it already).
  Turn take();

 private:
  void wait();
  void give_back();

  std::timed_mutex busy_;
  std::atomic<std::thread::id> owner_{};
};

}  // namespace nck::py
