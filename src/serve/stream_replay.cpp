#include "nck/serve/stream_replay.hpp"

#include <fmt/format.h>

namespace nck::app::serve {

std::string StreamReplay::number(const std::string& frame, bool keep) {
  const std::uint64_t id = next_id_++;
  std::string out = fmt::format("id: {}\n{}", id, frame);
  if (!keep) return out;
  kept_.emplace_back(id, out);
  kept_bytes_ += out.size();
  while (kept_bytes_ > max_bytes_ && kept_.size() > 1) {
    kept_bytes_ -= kept_.front().second.size();
    dropped_up_to_ = kept_.front().first;
    kept_.pop_front();
  }
  return out;
}

std::string StreamReplay::since(std::uint64_t last_id) const {
  std::string out;
  // An events frame after last_id that is no longer kept: say so, once.
  if (dropped_up_to_ > last_id)
    out = fmt::format("event: lost\ndata: {{\"after_id\":{},\"up_to_id\":{}}}\n\n", last_id, dropped_up_to_);
  for (const auto& [id, frame] : kept_)
    if (id > last_id) out += frame;
  return out;
}

}  // namespace nck::app::serve
