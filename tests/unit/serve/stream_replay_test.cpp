// The stream's ids and Last-Event-ID replay (issue 47, item 6): every frame
// numbered, events frames kept up to the byte bound, a `lost` frame when a
// client comes back later than that.
#include <gtest/gtest.h>

#include "nck/serve/stream_replay.hpp"

namespace nck::app::serve {
namespace {

TEST(StreamReplay, NumbersEveryFrameAndReplaysTheEventsAfterAnId) {
  StreamReplay r;
  EXPECT_EQ(r.number("event: state\ndata: {}\n\n", false), "id: 1\nevent: state\ndata: {}\n\n");
  const std::string e2 = r.number("event: events\ndata: [2]\n\n", true);
  r.number("event: state\ndata: {}\n\n", false);
  const std::string e4 = r.number("event: events\ndata: [4]\n\n", true);
  EXPECT_EQ(e4, "id: 4\nevent: events\ndata: [4]\n\n");
  EXPECT_EQ(r.since(1), e2 + e4);
  EXPECT_EQ(r.since(2), e4);  // the state frame 3 is not replayed: the new state follows
  EXPECT_EQ(r.since(4), "");
}

TEST(StreamReplay, SaysWhatItNoLongerHolds) {
  StreamReplay r(40);  // room for one kept frame of these
  r.number("event: events\ndata: [1]\n\n", true);
  r.number("event: events\ndata: [2]\n\n", true);
  const std::string e3 = r.number("event: events\ndata: [3]\n\n", true);
  EXPECT_EQ(r.since(0), "event: lost\ndata: {\"after_id\":0,\"up_to_id\":2}\n\n" + e3);
  EXPECT_EQ(r.since(2), e3);  // nothing after 2 was lost
}

}  // namespace
}  // namespace nck::app::serve
