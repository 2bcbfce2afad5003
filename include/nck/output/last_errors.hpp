#pragma once
// The last error of each channel, as the state document shows it
// (`last_error`, docs/api.md and docs/python.md): taken from the run's
// events, so an error while a program or an MDI text executes is there
// however it came (the stream and the events carry the same diagnostic).
// A reset of the channel clears it; a new run starts without one.
#include <array>
#include <cstddef>

#include <nlohmann/json.hpp>

#include "nck/config/machine.hpp"
#include "nck/kernel/event.hpp"
#include "nck/output/output_writers.hpp"

namespace nck::app {

class LastErrors {
 public:
  // An error event is kept (the diagnostic's one shape); a state event
  // with reason reset clears its channel's and the machine's.
  void take(const kernel::Event& e, const RunNames& names);
  // The operator's reset of channel ch (1-based): also of a channel that
  // is idle already (after an MDI error), which changes no program state.
  void clear(std::size_t ch);
  // The last error of channel ch (1-based; 0: the machine's, errors of no
  // channel), or null.
  const nlohmann::ordered_json& channel(std::size_t ch) const;
  // The newest of them all, or null.
  const nlohmann::ordered_json& latest() const;

 private:
  std::array<nlohmann::ordered_json, config::kMaxChannels + 1> by_channel_{};
  std::array<std::uint64_t, config::kMaxChannels + 1> order_{};  // when each was taken (0: none)
  std::uint64_t taken_ = 0;
};

}  // namespace nck::app
