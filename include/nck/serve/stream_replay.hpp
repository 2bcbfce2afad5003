#pragma once
// The stream's event ids and what a client that reconnects missed
// (server-sent events: `id:` on every frame, `Last-Event-ID` on reconnect).
// Every frame gets the next id; the events frames are kept up to a byte
// bound, so a client that comes back within it gets every event it missed
// in order (state frames are not kept: the current state replaces them).
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <utility>

namespace nck::app::serve {

class StreamReplay {
 public:
  explicit StreamReplay(std::size_t max_kept_bytes = std::size_t{4} << 20) : max_bytes_(max_kept_bytes) {}
  // "id: N\n" + frame; an events frame (`keep`) is kept for replay.
  std::string number(const std::string& frame, bool keep);
  // The kept frames after `last_id`, in order; when the oldest of those is
  // gone, an `event: lost` frame first that says which ids were lost.
  std::string since(std::uint64_t last_id) const;

 private:
  std::deque<std::pair<std::uint64_t, std::string>> kept_;
  std::size_t kept_bytes_ = 0;
  std::size_t max_bytes_;
  std::uint64_t next_id_ = 1;
  std::uint64_t dropped_up_to_ = 0;  // the highest id that was dropped from kept_ (or never kept)
};

}  // namespace nck::app::serve
