#include "py_interrupt.hpp"

#include <pybind11/pybind11.h>

namespace nck::py {
namespace {

std::atomic<std::atomic<bool>*> g_target{nullptr};
std::atomic<bool> g_pressed{false};

void on_sigint(int) {
  g_pressed.store(true);
  if (std::atomic<bool>* f = g_target.load()) f->store(true);
}

bool in_main_thread() {
  const pybind11::object threading = pybind11::module_::import("threading");
  return threading.attr("current_thread")().is(threading.attr("main_thread")());
}

}  // namespace

CtrlC::CtrlC(std::atomic<bool>& flag) {
  if (!in_main_thread()) return;  // signals reach the main thread only
  g_pressed.store(false);
  g_target.store(&flag);
  struct sigaction sa{};
  sa.sa_handler = on_sigint;
  sigemptyset(&sa.sa_mask);
  installed_ = sigaction(SIGINT, &sa, &old_) == 0;
}

CtrlC::~CtrlC() {
  if (!installed_) return;
  sigaction(SIGINT, &old_, nullptr);
  g_target.store(nullptr);
}

void CtrlC::raise_if_pressed() const {
  if (!installed_ || !g_pressed.load()) return;
  PyErr_SetNone(PyExc_KeyboardInterrupt);
  throw pybind11::error_already_set();
}

}  // namespace nck::py
