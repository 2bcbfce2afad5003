#pragma once
// Why a command should stop early: SIGINT/SIGTERM, or the --max-wall
// deadline. The stop flag is the one global state of nck (a signal handler
// can reach nothing else); the run loop reads it every cycle and the decoder
// at every block it reads (DecoderConfig::stop), so neither a long run nor a
// decoder stuck in a program's loops outlives a signal or the deadline.
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace nck::app {

// First thing in main: SIGINT and SIGTERM request a stop; SIGPIPE and
// SIGXFSZ are ignored, so a closed pipe or the file-size limit is a failed
// write (checked: 940002, exit 2, no temporary left), not a kill.
void install_signal_handlers();

// Set by a stop signal or by WallClockLimit.
const std::atomic<bool>& stop_flag();
// SIGINT / SIGTERM when one of them requested the stop, else 0.
int stop_signal();
// The exit code of a command a signal stopped: 130 / 143 (0: none came).
int signal_exit_code();

// Raises the stop flag once `limit_s` seconds of wall time have passed
// (0: never), from a thread that sleeps until then; reached() tells whether
// it did. Elapsed time, not a cycle count: slow cycles cannot overrun it.
class WallClockLimit {
 public:
  // flag: the stop flag to raise (nullptr: the process's, stop_flag()).
  explicit WallClockLimit(double limit_s, std::atomic<bool>* flag = nullptr);
  ~WallClockLimit();
  WallClockLimit(const WallClockLimit&) = delete;
  WallClockLimit& operator=(const WallClockLimit&) = delete;
  bool reached() const { return reached_.load(); }

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;  // the command ended first
  std::atomic<bool> reached_{false};
  std::thread watcher_;
};

}  // namespace nck::app
