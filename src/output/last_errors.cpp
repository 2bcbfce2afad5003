#include "nck/output/last_errors.hpp"

#include "nck/kernel/channel_events.hpp"
#include "nck/output/diagnostic_json.hpp"

namespace nck::app {

namespace {
const nlohmann::ordered_json kNone = nullptr;
}  // namespace

void LastErrors::take(const kernel::Event& e, const RunNames& names) {
  if (e.channel >= by_channel_.size()) return;
  if (const auto* error = e.get<kernel::ev::Error>()) {
    const std::string file = e.channel > 0 ? names.file(e.channel_index(), e.at.file_id) : std::string();
    by_channel_[e.channel] = diagnostic_json(error->id, names.text(error->id, error->message),
                                             SourceLoc{file, e.at.line, 0}, e.channel, Severity::error);
    order_[e.channel] = ++taken_;
    return;
  }
  const auto* state = e.get<kernel::ev::State>();
  if (state && state->reason == kernel::StateReason::reset) clear(e.channel);
}

void LastErrors::clear(std::size_t ch) {
  if (ch >= by_channel_.size()) return;
  by_channel_[ch] = nullptr;
  order_[ch] = 0;
  by_channel_[0] = nullptr;  // a machine error (a spindle's) is acknowledged by any channel's reset
  order_[0] = 0;
}

const nlohmann::ordered_json& LastErrors::channel(std::size_t ch) const {
  return ch < by_channel_.size() ? by_channel_[ch] : kNone;
}

const nlohmann::ordered_json& LastErrors::latest() const {
  std::size_t newest = 0;
  for (std::size_t ch = 1; ch < order_.size(); ++ch)
    if (order_[ch] > order_[newest]) newest = ch;
  return order_[newest] > 0 ? by_channel_[newest] : kNone;
}

}  // namespace nck::app
