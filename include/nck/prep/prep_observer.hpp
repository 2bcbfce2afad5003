#pragma once
// An optional watcher of a channel's block preparation (setup side): `nck
// run --report` sets one to draw the programmed contour beside the
// tool-centre path of tool radius compensation. Without one, preparation
// does nothing extra.
#include "nck/nc/block.hpp"

namespace nck::prep {

class Planner;

class PrepObserver {
 public:
  virtual ~PrepObserver() = default;
  // A decoded block before tool radius compensation rewrites it. `planner`
  // has planned every block before it unless compensation holds some
  // (`trc_holding`): then its position lags behind the program's.
  virtual void decoded(const nc::Block& b, const Planner& planner, bool trc_holding) = 0;
};

}  // namespace nck::prep
