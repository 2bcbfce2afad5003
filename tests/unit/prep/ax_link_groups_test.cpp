// The coupling-group rules on their own (TF5200 #SET AX LINK, spindle_link seed):
// a channel X Y1 Z1 Y2 with spindles S1 (6, main), S2 (11), S3 (17).
#include <gtest/gtest.h>

#include "nck/prep/ax_link_groups.hpp"

namespace nck::prep {
namespace {

config::ChannelConfig channel() {
  config::ChannelConfig c;
  const std::pair<const char*, std::uint32_t> axes[] = {{"X", 3}, {"Y1", 1}, {"Z1", 2}, {"Y2", 4}};
  for (auto [n, nr] : axes) c.axes.push_back({n, nr, -1});
  const std::pair<const char*, std::uint32_t> sp[] = {{"S1", 6}, {"S2", 11}, {"S3", 17}};
  for (auto [n, nr] : sp) {
    config::ChannelSpindle s;
    s.name = n;
    s.log_axis_nr = nr;
    c.spindles.push_back(s);
  }
  c.main_spindle_ax_nr = 6;
  c.default_link_group.pairs.push_back({"Y2", "Y1", 4, 1, 0});
  c.default_link_group.pairs.push_back({"S2", "S1", 11, 6, 1});
  return c;
}

nc::SetAxLink def(int g, std::vector<std::pair<std::string, std::string>> pairs, bool nbr = false) {
  nc::SetAxLink s;
  s.group = g;
  s.by_number = nbr;
  for (auto& [a, b] : pairs) {
    nc::AxLinkPair p;
    p.slave = a;
    p.master = b;
    s.pairs.push_back(p);
  }
  return s;
}

TEST(AxLinkGroups, GroupZeroComesFromTheChannelListByNumbers) {
  const auto c = channel();
  AxLinkGroups g(c, 0);
  auto r = g.enable(std::nullopt);
  ASSERT_TRUE(r) << r.error().message;
  ASSERT_EQ((*r)->pairs.size(), 2u);
  EXPECT_FALSE((*r)->pairs[0].slave.spindle);
  EXPECT_EQ((*r)->pairs[0].slave.index, 3);   // Y2
  EXPECT_EQ((*r)->pairs[0].master.index, 1);  // Y1
  EXPECT_TRUE((*r)->pairs[1].slave.spindle);
  EXPECT_EQ((*r)->pairs[1].slave.index, 1);   // S2
  EXPECT_TRUE(g.axis_is_slave(3));
  EXPECT_TRUE(g.spindle_is_slave(1));
  EXPECT_EQ(g.slaves_of_spindle(0), std::vector<int>{1});
}

TEST(AxLinkGroups, NamesAndNumbersResolveToTheSameSpindles) {
  const auto c = channel();
  AxLinkGroups g(c, 0);
  ASSERT_TRUE(g.define(def(1, {{"S2", "S"}, {"S3", "S"}})));
  ASSERT_TRUE(g.define(def(2, {{"11", "6"}, {"17", "6"}}, true)));
  auto a = g.enable(1);
  ASSERT_TRUE(a);
  EXPECT_EQ((*a)->pairs[0].master.index, 0);
  EXPECT_EQ((*a)->pairs[1].slave.index, 2);
  EXPECT_EQ(g.slaves_of_spindle(0), (std::vector<int>{1, 2}));
  // group 2 couples the same slaves: 21283
  auto b = g.enable(2);
  ASSERT_FALSE(b);
  EXPECT_EQ(b.error().id, ErrorId::AxLinkSlaveAlreadySlave);
  auto off = g.disable(nc::DisableAxLink{});
  ASSERT_TRUE(off);
  EXPECT_EQ(*off, 1u << 1);
  EXPECT_TRUE(g.enable(2));
}

TEST(AxLinkGroups, MixedPairWrongMixedGroupAllowed) {
  const auto c = channel();
  AxLinkGroups g(c, 0);
  auto bad = g.define(def(1, {{"Y2", "S"}, {"S2", "X"}}));
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().id, ErrorId::AxLinkMixedPair);
  EXPECT_TRUE(g.define(def(1, {{"Y2", "X"}, {"S2", "S"}})));
}

TEST(AxLinkGroups, MainSpindleRules) {
  const auto c = channel();
  AxLinkGroups g(c, 0);
  ASSERT_TRUE(g.define(def(1, {{"S2", "S"}})));
  ASSERT_TRUE(g.change_main_spindle(2));  // S3 is main now: group 1 named S = S1
  auto e = g.enable(1);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().id, ErrorId::AxLinkNamesChanged);
  ASSERT_TRUE(g.change_main_spindle(0));
  ASSERT_TRUE(g.enable(1));
  auto m = g.change_main_spindle(1);  // S2 is coupled
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().id, ErrorId::AxLinkMainSpindleLinked);
}

TEST(AxLinkGroups, MaximaAndScaling) {
  const auto c = channel();
  AxLinkGroups g(c, 0);
  EXPECT_EQ(g.define(def(32, {{"S2", "S"}})).error().id, ErrorId::AxLinkGroupRange);
  nc::SetAxLink m = def(3, {{"Y2", "Y1"}});
  m.pairs[0].numerator = -1;
  m.pairs[0].denominator = 2;
  ASSERT_TRUE(g.define(m));
  auto r = g.enable(3);
  ASSERT_TRUE(r);
  EXPECT_DOUBLE_EQ((*r)->pairs[0].ratio, -0.5);
  EXPECT_EQ(g.disable_all(), 1u << 3);
  EXPECT_EQ(g.disable(nc::DisableAxLink{3, false}).error().id, ErrorId::AxLinkNotEnabled);
}

}  // namespace
}  // namespace nck::prep
