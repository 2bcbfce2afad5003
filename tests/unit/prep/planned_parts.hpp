#pragma once
// What tests read of a planned command: its attachments of one kind, and
// the parts of its step.
#include <vector>

#include "nck/prep/planned_command.hpp"

namespace nck::test {

template <class T>
std::vector<T> attached(const prep::PlannedCommand& c) {
  std::vector<T> r;
  c.each<T>([&](const T& a) { r.push_back(a); });
  return r;
}

// The error a command raises (none for another kind).
inline kernel::Error error_of(const prep::PlannedCommand& c) {
  const auto* e = std::get_if<kernel::Error>(&c.step);
  return e ? *e : kernel::Error{};
}

inline kernel::EndReason end_reason_of(const prep::PlannedCommand& c) {
  const auto* e = std::get_if<kernel::End>(&c.step);
  return e ? e->reason : kernel::EndReason::error;
}

}  // namespace nck::test
