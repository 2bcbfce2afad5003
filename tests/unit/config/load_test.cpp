#include "nck/config/load.hpp"

#include <gtest/gtest.h>

#include "machine_folder.hpp"

namespace nck::config {
namespace {

using test::dump;
using test::MachineFolder;
using test::with_id;

LoadResult load_example(const char* name) {
  return load_machine(std::filesystem::path(NCK_SOURCE_DIR) / "examples" / name);
}

TEST(LoadExamples, MillIsCleanAndConverted) {
  auto r = load_example("mill");
  ASSERT_TRUE(r.machine) << dump(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty()) << dump(r.diagnostics);
  const Machine& m = *r.machine;
  ASSERT_EQ(m.channels.size(), 1u);
  const auto& c = m.channels[0];
  // X Y Z and the main spindle S1 as C axis (axis_mode 0x0204, #CAX).
  ASSERT_EQ(c.axes.size(), 4u);
  EXPECT_EQ(c.axes[2].name, "Z");
  EXPECT_EQ(c.axes[2].axis_index, 2);
  EXPECT_EQ(c.c_axis, 3);
  EXPECT_EQ(c.axes[3].name, "C");
  EXPECT_EQ(c.axes[3].axis_index, 3);  // S1's list
  EXPECT_EQ(c.trafo_ids[0], 14u);
  EXPECT_EQ(c.trafo_ids[1], 15u);
  ASSERT_EQ(c.spindles.size(), 2u);
  EXPECT_EQ(c.spindles[0].name, "S1");
  EXPECT_EQ(c.spindles[0].axis_index, 3);
  EXPECT_EQ(c.spindles[0].m3_sync, sync::PLC_INFO | sync::MVS_SVS);
  EXPECT_EQ(c.spindles[0].m4_sync, 0x00020004u);
  EXPECT_DOUBLE_EQ(c.spindles[0].m3_ack_timeout_s, 2.0);
  EXPECT_EQ(c.main_spindle_ax_nr, 4u);
  const AxisConfig& x = m.axes[0];
  EXPECT_DOUBLE_EQ(x.gear(1).max_speed_mm_s, 500.0);  // 500000 um/s = 30 m/min
  EXPECT_DOUBLE_EQ(x.gear(1).a_max, 3000.0);
  EXPECT_DOUBLE_EQ(x.sw_limit_pos, 500.0);
  const AxisConfig& s1 = m.axes[3];
  EXPECT_TRUE(s1.is_spindle());
  EXPECT_DOUBLE_EQ(s1.gear(1).max_speed_mm_s, 72000.0);  // 12000 rpm in deg/s
  EXPECT_TRUE(c.dist_ctrl_enabled());
  EXPECT_DOUBLE_EQ(c.dist_ctrl.a_max_mm_s2, 500.0);
  EXPECT_DOUBLE_EQ(c.dist_ctrl.max_deviation_mm, 5.0);
  EXPECT_EQ(c.dist_ctrl.filter_type, DistFilter::moving_average);
  EXPECT_EQ(c.decoder_function & decoder_fct::FCT_USE_CACHED_FILES, decoder_fct::FCT_USE_CACHED_FILES);
  ASSERT_EQ(c.default_link_group.pairs.size(), 1u);
  EXPECT_EQ(c.default_link_group.pairs[0].slave, "S2");
  EXPECT_EQ(c.default_link_group.pairs[0].master, "S1");
  const auto& data = m.channel_data[0];
  ASSERT_GE(data.tools.size(), 6u);
  EXPECT_DOUBLE_EQ(data.tools[1].length_mm, 100.0);
  EXPECT_DOUBLE_EQ(data.tools[5].vb_max_rpm, 500.0);
  EXPECT_DOUBLE_EQ(data.zero.versch[1][0], 100.0);   // G54 X
  EXPECT_DOUBLE_EQ(data.zero.versch[2][1], 100.0);   // G55 Y
  EXPECT_DOUBLE_EQ(data.clamp.versatz[1][1], -5.0);
  EXPECT_DOUBLE_EQ(m.sim.plc_ack_delay_s, 0.01);
  EXPECT_EQ(m.sim.surface, SurfaceKind::sine);
  EXPECT_DOUBLE_EQ(m.sim.surface_amplitude_mm, 0.5);
  EXPECT_EQ(m.cycle_time_us, 1000u);
}

TEST(LoadExamples, LatheHasThreeGearStages) {
  auto r = load_example("lathe");
  ASSERT_TRUE(r.machine);
  EXPECT_TRUE(r.diagnostics.empty()) << dump(r.diagnostics);
  const auto& c = r.machine->channels[0];
  EXPECT_TRUE(c.main_spindle_gear_change);
  ASSERT_EQ(c.spindles.size(), 1u);
  const auto& s = c.spindles[0];
  EXPECT_TRUE(s.autom_range);
  EXPECT_DOUBLE_EQ(s.range_table[1].min_speed_rpm, 600);
  EXPECT_DOUBLE_EQ(s.range_table[2].max_speed_rpm, 8000);
  EXPECT_EQ(s.range_way[0], 1);
  const AxisConfig& a = r.machine->axes[static_cast<std::size_t>(s.axis_index)];
  EXPECT_TRUE(a.gear(2).given);
  EXPECT_FALSE(a.gear(4).given);
  EXPECT_DOUBLE_EQ(a.gear(1).max_speed_mm_s, 4800.0);  // 800 rpm
  EXPECT_DOUBLE_EQ(a.gear(2).gear_change_pos_deg, 45.0);
  EXPECT_EQ(a.gear(3).curve.type, 2u);
  EXPECT_DOUBLE_EQ(a.gear(3).curve.limit_speed_deg_s, 12000.0);
  EXPECT_DOUBLE_EQ(a.gear(3).curve.b3, -1.92901234e-10);
  EXPECT_EQ(c.m_synch[41], sync::MVS_SVS);
}

TEST(LoadExamples, TwoChannelsShareSpindles) {
  auto r = load_example("two-channel");
  ASSERT_TRUE(r.machine);
  EXPECT_TRUE(r.diagnostics.empty()) << dump(r.diagnostics);
  const auto& m = *r.machine;
  ASSERT_EQ(m.channels.size(), 2u);
  EXPECT_EQ(m.channels[0].spindles.size(), 3u);
  EXPECT_EQ(m.channels[1].spindles.size(), 2u);
  EXPECT_EQ(m.channels[0].main_spindle_ax_nr, 11u);
  EXPECT_EQ(m.channels[1].main_spindle_ax_nr, 11u);
  EXPECT_EQ(m.channels[0].spindles[1].axis_index, m.channels[1].spindles[1].axis_index);
  EXPECT_EQ(m.channels[1].axes[0].name, "X");
  EXPECT_EQ(m.channels[1].axes[0].log_axis_nr, 4u);
  const AxisConfig* s3 = m.axis_by_log_nr(30);
  ASSERT_NE(s3, nullptr);
  EXPECT_EQ(s3->axis_mode, 0x40000u);  // PLC spindle written in the seed's short form
  EXPECT_TRUE(s3->is_spindle());
}

TEST(Load, MinimalMachineDefaults) {
  MachineFolder f;
  auto r = f.load();
  ASSERT_TRUE(r.machine);
  EXPECT_TRUE(r.ok()) << dump(r.diagnostics);
  const auto& m = *r.machine;
  EXPECT_EQ(m.cycle_time_us, 1000u);
  EXPECT_EQ(m.channels[0].spindles[0].m3_sync, sync::MVS_SVS);
  EXPECT_DOUBLE_EQ(m.axes[0].gear(1).max_speed_mm_s, 200.0);
  EXPECT_DOUBLE_EQ(m.axes[0].gear(1).position_gain_1_s, 10.0);
}

TEST(Load, MissingStartupIsFatal910001) {
  auto r = load_machine("/nonexistent/machine");
  EXPECT_FALSE(r.machine);
  ASSERT_EQ(r.diagnostics.items().size(), 1u);
  EXPECT_EQ(r.diagnostics.items()[0].id, ErrorId::ConfigFileUnreadable);
  EXPECT_NE(r.diagnostics.items()[0].message.find("startup.lis"), std::string::npos);
}

TEST(Load, MissingListNamesPathAndStartupLine) {
  MachineFolder f;
  f.append("startup.lis", "werkz_data[0] missing_tools.lis\n");
  auto r = f.load();
  auto e = with_id(r.diagnostics, ErrorId::ConfigFileUnreadable);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].loc.file, f.file("startup.lis"));
  EXPECT_EQ(e[0].loc.line, 4u);
  EXPECT_NE(e[0].message.find("missing_tools.lis"), std::string::npos);
}

TEST(Load, DefaultListsAndBackslashPaths) {
  MachineFolder f;
  f.write("startup.lis", "default_achs_mds dflt.lis\nsda_mds[0] sub\\ch.lis\nachs_mds[0] x.lis\nachs_mds[1] s1.lis\n");
  std::filesystem::create_directories(f.dir() / "sub");
  f.write("sub/ch.lis", test::minimal_machine()["ch.lis"]);
  f.write("dflt.lis", "getriebe[0].kv 3000\n");
  auto r = f.load();
  ASSERT_TRUE(r.machine);
  EXPECT_TRUE(r.ok()) << dump(r.diagnostics);
  EXPECT_DOUBLE_EQ(r.machine->axes[0].gear(1).position_gain_1_s, 30.0);
}

TEST(Load, GarbageStartupNeverCrashes) {
  MachineFolder f;
  std::string junk;
  for (int i = 0; i < 5000; ++i) junk.push_back(static_cast<char>((i * 7919) & 0xff));
  f.write("startup.lis", junk);
  auto r = f.load();
  ASSERT_TRUE(r.machine);
  EXPECT_TRUE(r.diagnostics.has_errors());
}

}  // namespace
}  // namespace nck::config
