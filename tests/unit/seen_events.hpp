#pragma once
// Tests look at events of one kind: each with its head's fields (t_s,
// channel, at) and its payload's side by side.
#include <vector>

#include "nck/kernel/event.hpp"

namespace nck::test {

template <class T>
struct Seen : EventHead, T {};

// The events of payload type T among `events`, in their order.
template <class T, class Events>
std::vector<Seen<T>> seen(const Events& events) {
  std::vector<Seen<T>> r;
  for (const kernel::Event& e : events)
    if (const T* p = e.template get<T>()) r.push_back(Seen<T>{static_cast<const EventHead&>(e), *p});
  return r;
}

// The ID of a warning or error event; none for another kind.
inline ErrorId diagnosis_id(const kernel::Event& e) {
  if (const auto* w = e.get<kernel::ev::Warning>()) return w->id;
  if (const auto* x = e.get<kernel::ev::Error>()) return x->id;
  return ErrorId{};
}

// Every cycle's events, kept (take() after each tick).
struct EventLog {
  std::vector<kernel::Event> events;
  template <class Output>
  void take(const Output& out) {
    events.insert(events.end(), out.events.begin(), out.events.end());
  }
  int count(ErrorId id) const {
    int n = 0;
    for (const kernel::Event& e : events) n += diagnosis_id(e) == id;
    return n;
  }
};

}  // namespace nck::test
