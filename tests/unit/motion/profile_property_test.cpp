// Seeded property tests: random lengths, limits, cycle times and override
// sequences (feedholds included). Never exceed a limit, always reach the
// target exactly, never NaN. Count from NCK_PROPERTY_COUNT (default 500);
// every failure prints its seed so it can be replayed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <expected>
#include <numbers>
#include <random>
#include <string>

#include "nck/motion/limits.hpp"
#include "nck/motion/path_profile.hpp"
#include "nck/motion/segment.hpp"

namespace nck::motion {
namespace {

int property_count() {
  const char* env = std::getenv("NCK_PROPERTY_COUNT");
  if (env == nullptr) return 500;
  const int n = std::atoi(env);
  return n > 0 ? n : 500;
}

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
double log_uniform(Rng& rng, double lo, double hi) {
  return std::exp(uniform(rng, std::log(lo), std::log(hi)));
}

double random_length(Rng& rng) {
  const double pick = uniform(rng, 0.0, 1.0);
  if (pick < 0.05) return 0.0;
  if (pick < 0.25) return log_uniform(rng, 1e-9, 1e-2);
  if (pick < 0.95) return uniform(rng, 0.0, 500.0);
  return uniform(rng, 500.0, 5000.0);
}

// A new override every `hold` cycles, 0 (feedhold) one time in five; after
// the last change a steady override so that the move must end.
struct OverrideSchedule {
  std::array<double, 12> value{};
  std::array<int, 12> cycles{};
  explicit OverrideSchedule(Rng& rng) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      value[i] = uniform(rng, 0.0, 1.0) < 0.2 ? 0.0 : uniform(rng, 0.01, 1.5);
      cycles[i] = static_cast<int>(uniform(rng, 1.0, 400.0));
    }
    value.back() = uniform(rng, 0.5, 1.2);
  }
  int total_cycles() const {
    int n = 0;
    for (std::size_t i = 0; i + 1 < cycles.size(); ++i) n += cycles[i];
    return n;
  }
  double at(int k) const {
    for (std::size_t i = 0; i + 1 < value.size(); ++i) {
      if (k < cycles[i]) return value[i];
      k -= cycles[i];
    }
    return value.back();
  }
};

TEST(ProfileProperty, NeverExceedsAlwaysArrives) {
  const int count = property_count();
  const std::array<double, 4> cycle_s{0.0005, 0.001, 0.002, 0.004};
  for (int c = 0; c < count; ++c) {
    const auto seed = static_cast<Rng::result_type>(1000 + c);
    Rng rng(seed);
    const PathLimits lim{log_uniform(rng, 0.5, 2000.0), log_uniform(rng, 5.0, 50000.0),
                         log_uniform(rng, 5.0, 50000.0)};
    const double v_cmd = log_uniform(rng, 0.5, 3000.0);
    // At most ~20 s of motion at full speed keeps a case below ~1e5 cycles.
    const double len = std::min(random_length(rng), 20.0 * std::min(v_cmd, lim.v_max_mm_s));
    const double v_end = uniform(rng, 0.0, 1.0) < 0.3 ? uniform(rng, 0.0, lim.v_max_mm_s) : 0.0;
    const double dt = cycle_s[static_cast<std::size_t>(uniform(rng, 0.0, 3.999))];
    const OverrideSchedule ovr(rng);
    SCOPED_TRACE("seed " + std::to_string(seed) + " L=" + std::to_string(len) +
                 " dt=" + std::to_string(dt));

    PathProfile p;
    ASSERT_TRUE(p.start(len, v_cmd, lim, v_end));
    // Bound: the schedule, then the whole move at the slowest steady override
    // (0.5), plus slack for the ramps. Never crawling forever.
    const double t_slow = duration_estimate(len, 0.5 * std::min(v_cmd, lim.v_max_mm_s), lim);
    const int max_cycles = ovr.total_cycles() + static_cast<int>(2.0 * t_slow / dt) + 100;
    double s_prev = p.s(), v_prev = 0.0;
    int k = 0;
    bool ok = true;
    for (; k < max_cycles && !p.finished() && ok; ++k) {
      const ProfileSample smp = p.step(dt, ovr.at(k));
      const double v = smp.v_mm_s;
      ok = std::isfinite(smp.s_mm) && std::isfinite(v) && v >= 0.0 &&
           v <= lim.v_max_mm_s * (1 + 1e-9) &&
           v - v_prev <= lim.a_acc_mm_s2 * dt * (1 + 1e-6) + 1e-9 &&
           v_prev - v <= lim.a_dec_mm_s2 * dt * (1 + 1e-6) + 1e-9 && smp.s_mm >= s_prev &&
           smp.s_mm <= len && smp.s_mm - s_prev <= v * dt * (1 + 1e-9) + 1e-12;
      EXPECT_TRUE(ok) << "cycle " << k << " s=" << smp.s_mm << " v=" << v << " v_prev=" << v_prev
                      << " limits " << lim.v_max_mm_s << "/" << lim.a_acc_mm_s2 << "/"
                      << lim.a_dec_mm_s2;
      s_prev = smp.s_mm;
      v_prev = v;
    }
    ASSERT_TRUE(p.finished()) << "not finished after " << k << " cycles";
    EXPECT_EQ(p.s(), len);
    if (v_end == 0.0) {
      EXPECT_LE(v_prev, lim.a_dec_mm_s2 * dt * (1 + 1e-9) + 1e-12);
    }
    if (!ok) return;  // one detailed failure is enough
  }
}

// Geometry + limits + profile together: stepping random lines and arcs at the
// computed path limits keeps every axis within its own limits (finite
// differences of the set points; 1 % slack for the chord effect on arcs).
TEST(ProfileProperty, AxesStayWithinTheirLimits) {
  const int count = std::max(property_count() / 5, 20);
  constexpr double dt = 0.001;
  for (int c = 0; c < count; ++c) {
    const auto seed = static_cast<Rng::result_type>(50000 + c);
    Rng rng(seed);
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::array<AxisDynamics, 3> ax{};
    for (auto& a : ax) {
      a = {log_uniform(rng, 10.0, 1000.0), log_uniform(rng, 50.0, 20000.0),
           log_uniform(rng, 50.0, 20000.0)};
    }
    AxisVector s{}, e{};
    for (std::size_t i = 0; i < 3; ++i) {
      s[i] = uniform(rng, -50.0, 50.0);
      e[i] = uniform(rng, -50.0, 50.0);
    }
    std::expected<Segment, ArcError> seg = make_line(s, e, 3);
    if (uniform(rng, 0.0, 1.0) < 0.6) {
      // |R| at least half the chord (plus a margin), 30 % long arcs, Z as helix axis.
      const double half_chord = std::hypot(e[0] - s[0], e[1] - s[1]) / 2.0;
      const double r = std::max(log_uniform(rng, 0.5, 100.0), half_chord + 0.1);
      const bool long_arc = uniform(rng, 0.0, 1.0) < 0.3;
      const bool ccw = uniform(rng, 0.0, 1.0) < 0.5;
      seg = make_arc_radius(s, e, 3, 0, 1, long_arc ? -r : r, ccw);
    }
    ASSERT_TRUE(seg);
    const PathLimits lim = path_limits(*seg, ax);
    PathProfile p;
    ASSERT_TRUE(p.start(seg->length(), 1e9, lim));  // rapid: as fast as the axes allow
    std::array<AxisVector, 3> hist{};  // positions k-2, k-1, k
    seg->point_at(0.0, hist[1]);
    hist[0] = hist[1];
    int k = 0;
    for (; k < 1000000 && !p.finished(); ++k) {
      const ProfileSample smp = p.step(dt, 1.0);
      seg->point_at(smp.s_mm, hist[2]);
      for (std::size_t i = 0; i < 3; ++i) {
        const double v1 = (hist[2][i] - hist[1][i]) / dt;
        const double v0 = (hist[1][i] - hist[0][i]) / dt;
        ASSERT_LE(std::abs(v1), ax[i].v_max_mm_s * 1.01 + 1e-6) << "axis " << i << " cycle " << k;
        const double acc = (v1 - v0) / dt;
        const double a_lim = std::max(ax[i].a_acc_mm_s2, ax[i].a_dec_mm_s2);
        ASSERT_LE(std::abs(acc), a_lim * 1.01 + 1e-6) << "axis " << i << " cycle " << k;
      }
      hist[0] = hist[1];
      hist[1] = hist[2];
    }
    ASSERT_TRUE(p.finished());
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(hist[1][i], e[i]);
  }
}

}  // namespace
}  // namespace nck::motion
