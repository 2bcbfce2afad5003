#include "nck/core/diagnostic.hpp"

#include <gtest/gtest.h>

#include <set>

namespace nck {

TEST(Diagnostic, FormatsFileLineSeverityAndId) {
  Diagnostic d = make_diagnostic(ErrorId::ConfigWegaufzZero, {"x.lis", 12, 0}, "wegaufz 0, using 1");
  EXPECT_EQ(format(d), "x.lis:12: warning 110386: wegaufz 0, using 1");
  Diagnostic e = make_diagnostic(ErrorId::NcFileUnreadable, {"p.nc", 3, 7}, "boom");
  EXPECT_EQ(format(e), "p.nc:3:7: error 920001: boom");
}

TEST(Diagnostic, SeverityComesFromTheTable) {
  EXPECT_EQ(make_diagnostic(ErrorId::ConfigDistCtrlAMaxMissing, {}, "").severity, Severity::error);
  EXPECT_EQ(make_diagnostic(ErrorId::ConfigWegaufnZero, {}, "").severity, Severity::warning);
}

TEST(Diagnostic, IdsAreUniqueAndDescribed) {
  std::set<std::uint32_t> seen;
  for (const ErrorInfo& e : all_errors()) {
    EXPECT_TRUE(seen.insert(number(e.id)).second) << "duplicate id " << number(e.id);
    EXPECT_FALSE(e.text.empty()) << e.name;
    EXPECT_FALSE(e.remedy.empty()) << e.name;
  }
}

TEST(Diagnostics, CountsErrorsNotWarnings) {
  Diagnostics ds;
  ds.add(ErrorId::ConfigWegaufzZero, {}, "w");
  EXPECT_FALSE(ds.has_errors());
  ds.add(ErrorId::ConfigBadValue, {}, "e");
  EXPECT_TRUE(ds.has_errors());
  EXPECT_EQ(ds.error_count(), 1u);
}

}  // namespace nck
