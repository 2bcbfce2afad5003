#include "nck/run/stop_at.hpp"

#include <charconv>

#include "nck/output/output_writers.hpp"

namespace nck::app {
std::optional<std::int64_t> whole_number(std::string_view s, std::int64_t lowest) {
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || end != s.data() + s.size() || v < lowest) return std::nullopt;
  return v;
}

namespace {

std::optional<StopAt> numbered(kernel::StopMark::Kind kind, std::string_view digits, std::int64_t lowest) {
  const auto v = whole_number(digits, lowest);
  if (!v) return std::nullopt;
  return StopAt{kernel::StopMark{kind, *v}, std::nullopt};
}

}  // namespace

std::optional<StopAt> parse_stop_at(std::string_view text) {
  using K = kernel::StopMark::Kind;
  if (text.size() > 1 && (text[0] == 'N' || text[0] == 'n')) return numbered(K::n, text.substr(1), 0);
  if (text.starts_with("line:")) return numbered(K::line, text.substr(5), 1);
  if (text.starts_with("block:")) return numbered(K::block, text.substr(6), 1);
  if (text.starts_with("event:")) {
    const auto kind = event_kind_from(text.substr(6));
    if (!kind) return std::nullopt;
    return StopAt{kernel::StopMark{}, *kind};
  }
  return std::nullopt;
}

StopAtWatch::StopAtWatch(const StopAt& stop_at, sim::DryRun& run) : stop_at_(stop_at), run_(&run) {
  for (std::size_t ch = 0; ch < run.channel_count(); ++ch) run.set_stop_at(ch, stop_at_.mark);
}

bool StopAtWatch::reached(const kernel::TickOutput& out) {
  for (const kernel::Event& e : out.events) {
    if (e.channel == 0) continue;
    const auto* state = e.get<kernel::ev::State>();
    if (state && state->to == kernel::ProgramState::hold && state->reason == kernel::StateReason::stop_at) return true;
    if (stop_at_.event && e.kind() == *stop_at_.event) {
      run_->set_stop_at(e.channel - 1u, kernel::StopMark{kernel::StopMark::Kind::now, 0});
      stop_at_.event.reset();  // the first such event marks its block
    }
  }
  return false;
}

}  // namespace nck::app
