#include "nck/run/stop_request.hpp"

#include <chrono>
#include <csignal>

namespace nck::app {
namespace {

static_assert(std::atomic<bool>::is_always_lock_free, "the stop flag is set from a signal handler");

std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_signal = 0;

void on_stop_signal(int sig) {
  g_signal = sig;
  g_stop.store(true, std::memory_order_relaxed);
}

}  // namespace

void install_signal_handlers() {
  struct sigaction sa{};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
}

const std::atomic<bool>& stop_flag() { return g_stop; }

int stop_signal() { return g_signal; }

int signal_exit_code() {
  if (g_signal == SIGINT) return 130;
  if (g_signal == SIGTERM) return 143;
  return 0;
}

WallClockLimit::WallClockLimit(double limit_s, std::atomic<bool>* flag) {
  if (!flag) flag = &g_stop;
  if (!(limit_s > 0)) return;
  constexpr double kMaxLimitS = 1e9;  // about 30 years: far below the clock's range
  if (limit_s > kMaxLimitS) limit_s = kMaxLimitS;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(limit_s));
  watcher_ = std::thread([this, deadline, flag] {
    std::unique_lock lock(mutex_);
    if (wake_.wait_until(lock, deadline, [this] { return done_; })) return;
    reached_.store(true);
    flag->store(true, std::memory_order_relaxed);
  });
}

WallClockLimit::~WallClockLimit() {
  if (!watcher_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  wake_.notify_one();
  watcher_.join();
}

}  // namespace nck::app
