// The report's plots folded on their own thread: the same tool path, cause
// timeline and envelopes (path.a and path.j derived there) as folding every
// cycle on the run's thread.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "nck/report/report_plots.hpp"

namespace nck::app {
namespace {

constexpr std::size_t kSeries = 3;
constexpr double kCycleS = 0.001;

struct Cycle {
  std::array<double, 3> pos;
  std::uint32_t line;
  bool rapid;
  kernel::CycleCause cause;
  std::array<double, kSeries> row;  // path velocity (path.a and path.j: derived by the plots)
};

// A run of arcs and lines over several blocks and causes: enough cycles for
// many batches and for the envelope to merge its buckets.
std::vector<Cycle> cycles(std::size_t n) {
  std::vector<Cycle> out;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * kCycleS;
    const auto line = static_cast<std::uint32_t>(i / 700 + 1);
    const bool arc = line % 2 == 0;
    const std::array<double, 3> pos{arc ? 10 * std::cos(t) : t, arc ? 10 * std::sin(t) : 0.5 * t, 0};
    const auto cause = i % 1900 < 300 ? kernel::CycleCause::corner : kernel::CycleCause::feed;
    out.push_back({pos, line, line % 5 == 0, cause, {std::sin(3 * t) + static_cast<double>(line), 0, 0}});
  }
  return out;
}

TEST(ReportPlots, FoldedOnTheirThreadAsOnTheRunsThread) {
  const std::vector<Cycle> run = cycles(70000);  // 137 batches, the envelope past its 4,096 buckets
  ReportPlots plots(1);
  plots.channel(0).path.add({.pos = {1, 0, 0}});
  plots.channel(0).velocity_column = 0;
  plots.channel(0).path_deriv = PathDerivatives(kCycleS);
  plots.start(kSeries, kCycleS);
  PathDerivatives derivatives(kCycleS);
  TimedPath path;
  path.add({.pos = {1, 0, 0}});
  EnvelopeSeries series;
  series.start(kSeries, kCycleS);
  std::vector<double> cause_t;
  kernel::CycleCause last = kernel::CycleCause::none;
  for (std::size_t i = 0; i < run.size(); ++i) {
    const Cycle& c = run[i];
    const double t = static_cast<double>(i) * kCycleS;
    ReportBatch& b = plots.batch();
    const std::size_t k = b.add(i, t);
    ReportBatch::ChannelSample& s = b.channel(k, 0);
    s.pos = c.pos;
    s.line = c.line;
    s.rapid = c.rapid;
    s.cause = c.cause;
    s.path_velocity_mm_s = c.row[0];
    b.row(k)[0] = c.row[0];
    if (b.full()) plots.publish();
    path.add({.pos = c.pos, .t_s = t, .line = c.line, .rapid = c.rapid});
    derivatives.update(c.row[0]);
    series.add(i, std::array<double, kSeries>{c.row[0], derivatives.a_mm_s2(), derivatives.j_mm_s3()});
    if (c.cause != last) cause_t.push_back(t);
    last = c.cause;
  }
  plots.finish();  // folds the last, partial batch too
  plots.finish();  // and a second call does nothing
  path.close();
  const TimedPath::Vertices want = path.vertices(TimedPath::kMaxVertices);
  const TimedPath::Vertices got = plots.channel(0).path.vertices(TimedPath::kMaxVertices);
  ASSERT_EQ(got.points.size(), want.points.size());
  for (std::size_t i = 0; i < got.points.size(); ++i) {
    EXPECT_EQ(got.points[i].pos, want.points[i].pos) << i;
    EXPECT_EQ(got.points[i].line, want.points[i].line) << i;
    EXPECT_EQ(got.points[i].rapid, want.points[i].rapid) << i;
    EXPECT_EQ(got.points[i].t_s, want.points[i].t_s) << i;
  }
  EXPECT_GT(series.stride(), 1u);
  EXPECT_EQ(plots.series().json({}), series.json({}));
  EXPECT_EQ(plots.channel(0).cause_t, cause_t);
  ASSERT_EQ(plots.channel(0).cause_name.size(), cause_t.size());
  EXPECT_EQ(plots.channel(0).cause_name[0], plots.channel(0).cause_name[2]);
  EXPECT_NE(plots.channel(0).cause_name[0], plots.channel(0).cause_name[1]);
}

TEST(ReportPlots, EndWithoutFinishingLeavesNoThreadBehind) {
  auto plots = std::make_unique<ReportPlots>(2);
  plots->start(1, kCycleS);
  for (std::size_t i = 0; i < 3 * ReportBatch::kCycles; ++i) {
    ReportBatch& b = plots->batch();
    b.row(b.add(i, static_cast<double>(i) * kCycleS))[0] = 1.0;
    if (b.full()) plots->publish();
  }
  plots.reset();  // the destructor folds what was handed over and joins
  SUCCEED();
}

}  // namespace
}  // namespace nck::app
