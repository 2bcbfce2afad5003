#pragma once
// The events a library user keeps in memory (the Python module), in a
// compact form: each event's JSON line of the --events schema, all in one
// text, and a 32-byte record of its head (time, channel, kind, line, N)
// that a session matches and numpy reads. A JSON object per event took
// about 640 bytes (1.3 KB with long paths) and a dict more; the text of a
// block event is about 80 bytes.
//
// Bounded by bytes (text + records): a run ends at the bound (end_run:
// error 940204, Simulation), while a session, whose events() drains the
// events, drops the oldest half and counts them (drop_oldest: warning 940205).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "nck/kernel/event.hpp"

namespace nck::app {

// The kind of a session's operator-action event ("operator"): after the
// kernel's kinds, as nck.EVENT_KINDS lists it. No kernel event has it.
inline constexpr std::uint8_t kOperatorEventKind = std::variant_size_v<kernel::EventPayload>;
inline constexpr const char* kOperatorEventName = "operator";

struct EventRecord {
  double t_s = 0;
  std::uint64_t text_end = 0;  // where the event's line ends in EventMemory::text
  std::int64_t n = -1;         // the block's N number; -1: none
  std::uint32_t line = 0;
  std::uint8_t channel = 0;
  std::uint8_t kind = 0;  // kernel::EventKind; kOperatorEventKind for an operator action
};

class EventMemory {
 public:
  enum class Full : std::uint8_t { end_run, drop_oldest };

  // setup: keep events from now on, at most `max_bytes` of them.
  void start(std::uint64_t max_bytes, Full policy);
  bool enabled() const { return enabled_; }
  // One event and its JSON line. end_run: false (and nothing kept) once
  // the event would pass the bound. drop_oldest: always kept.
  bool add(const kernel::Event& e, std::string_view line);
  // An event no kernel cycle made (a session's operator action): its head
  // as a record (text_end is filled in) and its JSON line; as add.
  bool add(EventRecord head, std::string_view line);
  // The closing events of a run that ended at the bound (state, end) are kept.
  void lift_bound() { lifted_ = true; }
  bool full() const { return full_; }
  // drop_oldest: how many were dropped since the last call.
  std::uint64_t take_dropped();

  std::size_t size() const { return records.size(); }
  std::string_view line(std::size_t i) const;
  // Every event ever added, counted from 0, and the count of the first one
  // still kept (a session asks whether an event came within a call).
  std::uint64_t total() const { return first_ + records.size(); }
  std::uint64_t first() const { return first_; }
  std::uint64_t bytes() const { return text.size() + records.size() * sizeof(EventRecord); }
  std::uint64_t max_bytes() const { return max_bytes_; }
  // A session's events() took them all.
  void clear();

  std::string text;  // the lines one after the other, without separators
  std::vector<EventRecord> records;

 private:
  void drop_oldest_half();

  bool enabled_ = false;
  bool full_ = false;
  bool lifted_ = false;
  Full policy_ = Full::end_run;
  std::uint64_t max_bytes_ = 0;
  std::uint64_t first_ = 0;
  std::uint64_t dropped_ = 0;
};

}  // namespace nck::app
