// ChannelFrames: a block's offset functions on the channel's offset chain,
// and the PCS <-> MCS maps. Blocks come from program texts decoded with the
// example machine's decoder configuration. Numbers from examples/mill
// (zero.lis G54 = X100 Y50 Z-150, G55 = X200 Y100 Z-150; tools.lis D1 =
// 100 mm, D2 = 125 mm; clamp.lis group 1 = X10 Y-5) and examples/lathe
// (G54 = Z200, D1 ax_versatz X25 Z50), worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "nck/prep/channel_frames.hpp"
#include "example_blocks.hpp"

namespace nck::prep {
namespace {

using testing::decode_blocks;
using testing::example_machine;

struct FramesRig {
  explicit FramesRig(const std::string& example, std::uint32_t clamp_index = 0)
      : machine(example_machine(example)),
        frames(machine.channels[0], machine.channel_data[0], machine.channels[0].axes.size(), clamp_index) {}

  // Decodes one program (the blocks share its modal state); next() then
  // applies its blocks one at a time.
  void load(const std::string& text) {
    blocks = decode_blocks(machine, text);
    at = 0;
  }
  // Applies the next block (the axes stand at `mcs_now`) and, as an absolute
  // move would, lets pending offsets act on every axis (unless !commit).
  FrameChanges next(const motion::AxisVector& mcs_now = {}, bool commit = true) {
    EXPECT_LT(at, blocks.size());
    if (at >= blocks.size()) return {};
    const nc::Block& b = blocks[at++];
    auto r = frames.apply(b, mcs_now);
    EXPECT_TRUE(r.has_value()) << "line " << b.line << ": " << (r ? "" : r.error().message);
    if (commit)
      for (std::size_t j = 0; j < machine.channels[0].axes.size(); ++j) frames.commit_axis(j);
    return r ? *r : FrameChanges{};
  }
  // load(text) and next() for each of its blocks but the last (M30).
  FrameChanges apply_all(const std::string& text) {
    load(text);
    FrameChanges last;
    while (at + 1 < blocks.size()) last = next();
    return last;
  }
  motion::AxisVector mcs(double x, double y, double z) const { return frames.to_mcs({x, y, z}, none); }
  motion::AxisVector pcs(double x, double y, double z) const { return frames.to_pcs({x, y, z}); }

  const config::Machine& machine;
  ChannelFrames frames;
  std::vector<nc::Block> blocks;
  std::size_t at = 0;
  frames::SuppressMask none = frames::SuppressMask::none();
};

void expect_xyz(const motion::AxisVector& v, double x, double y, double z) {
  EXPECT_NEAR(v[0], x, 1e-9);
  EXPECT_NEAR(v[1], y, 1e-9);
  EXPECT_NEAR(v[2], z, 1e-9);
}

bool has_kind(const FrameChanges& c, frames::OffsetKind k) {
  for (frames::OffsetKind x : c.kinds)
    if (x == k) return true;
  return false;
}

// to_pcs(to_mcs(p)) == p for a few points.
void expect_round_trip(const FramesRig& r) {
  for (const motion::AxisVector& p : {motion::AxisVector{0, 0, 0}, motion::AxisVector{12.5, -7, 3},
                                      motion::AxisVector{-40, 25, -60}}) {
    const motion::AxisVector back = r.frames.to_pcs(r.frames.to_mcs(p, r.none));
    expect_xyz(back, p[0], p[1], p[2]);
  }
}

TEST(ChannelFrames, WithoutOffsetsProgramAndMachineCoordinatesAgree) {
  FramesRig r("mill");
  expect_xyz(r.mcs(1, 2, 3), 1, 2, 3);
  expect_xyz(r.pcs(1, 2, 3), 1, 2, 3);
  EXPECT_TRUE(r.frames.affine(r.none).pure_translation);
}

TEST(ChannelFrames, ZeroOffsetSelection) {
  FramesRig r("mill");
  r.load("G54\nG55\nG53\nM30\n");
  FrameChanges c = r.next();
  EXPECT_TRUE(has_kind(c, frames::OffsetKind::zero));
  expect_xyz(r.mcs(0, 0, 50), 100, 50, -100);
  expect_xyz(r.pcs(100, 50, -150), 0, 0, 0);
  r.next();
  expect_xyz(r.mcs(0, 0, 0), 200, 100, -150);
  r.next();
  expect_xyz(r.mcs(0, 0, 0), 0, 0, 0);
}

// The list edited while the program runs (nck serve): the G54 in force
// keeps its value, its next selection takes the new one (TF5200: a zero
// offset's new value acts when the offset is next selected).
TEST(ChannelFrames, EditedZeroOffsetActsAtItsNextSelection) {
  FramesRig r("mill");
  r.load("G54\nG54\nM30\n");
  r.next();
  expect_xyz(r.mcs(0, 0, 0), 100, 50, -150);
  config::ZeroOffsets edited = r.machine.channel_data[0].zero;
  edited.versch[1][0] = 120;  // G54 X
  r.frames.set_zero_offsets(edited);
  expect_xyz(r.mcs(0, 0, 0), 100, 50, -150);
  r.next();
  expect_xyz(r.mcs(0, 0, 0), 120, 50, -150);
}

TEST(ChannelFrames, NewOffsetWaitsUntilItsAxisIsProgrammedAbsolutely) {
  FramesRig r("mill");
  r.load("G54\nM30\n");
  r.next({}, /*commit=*/false);
  // Selected at once (the offset event), acting per axis on commit.
  auto selected = r.frames.values_of(frames::OffsetKind::zero, true);
  ASSERT_EQ(selected.size(), 4u);  // X Y Z C
  EXPECT_DOUBLE_EQ(selected[0].second, 100.0);
  expect_xyz(r.mcs(0, 0, 0), 0, 0, 0);
  r.frames.commit_axis(0);
  expect_xyz(r.mcs(0, 0, 0), 100, 0, 0);
}

TEST(ChannelFrames, ToolLengthOnZ) {
  FramesRig r("mill");
  r.load("G54 D1\nD2\nD0\nM30\n");
  FrameChanges c = r.next();
  EXPECT_TRUE(has_kind(c, frames::OffsetKind::tool));
  expect_xyz(r.mcs(0, 0, 50), 100, 50, 0);  // 50 - 150 + 100
  r.next();
  expect_xyz(r.mcs(0, 0, 50), 100, 50, 25);  // 50 - 150 + 125
  r.next();
  expect_xyz(r.mcs(0, 0, 50), 100, 50, -100);
}

TEST(ChannelFrames, ToolLengthCorrectionAddsToTheLength) {
  FramesRig r("mill");
  // tools.nc N70/N80 with D1: Z-10 -> -10 + 100 + 0.5.
  r.load("D1\n#TLC ON [0.5]\n#TLC OFF\nM30\n");
  r.next();
  r.next();
  expect_xyz(r.mcs(0, 0, -10), 0, 0, 90.5);
  r.next();
  expect_xyz(r.mcs(0, 0, -10), 0, 0, 90);
}

TEST(ChannelFrames, UnknownToolIsError930011) {
  FramesRig r("mill");
  auto blocks = decode_blocks(r.machine, "D7\nM30\n");
  auto res = r.frames.apply(blocks.at(0), {});
  ASSERT_FALSE(res.has_value());
  EXPECT_EQ(res.error().id, ErrorId::KernelUnknownTool);
  EXPECT_EQ(res.error().loc.line, 1u);
}

TEST(ChannelFrames, G92ShiftsOnTopOfTheZeroOffset) {
  FramesRig r("mill");
  r.load("G54\nG92 X10\nG92 X0\nM30\n");
  r.next();
  FrameChanges c = r.next();
  EXPECT_TRUE(has_kind(c, frames::OffsetKind::g92));
  expect_xyz(r.mcs(0, 0, 0), 110, 50, -150);
  r.next();
  expect_xyz(r.mcs(0, 0, 0), 100, 50, -150);
}

TEST(ChannelFrames, ClampOffsetOfTheChosenGroup) {
  FramesRig r("mill", 1);
  expect_xyz(r.mcs(0, 0, 0), 10, -5, 0);
  r.apply_all("G54\nM30\n");
  expect_xyz(r.mcs(0, 0, 0), 110, 45, -150);
}

// The map as one point per main axis gives it (to_mcs of each unit vector
// minus the shift), compared bit for bit: affine() takes a shortcut when
// nothing turns, which must not change a digit.
void expect_map_as_by_columns(const FramesRig& r) {
  const AffineMap a = r.frames.affine(r.none);
  const motion::AxisVector shift = r.frames.to_mcs({}, r.none);
  EXPECT_EQ(a.shift, shift);
  for (std::size_t k = 0; k < 3; ++k) {
    motion::AxisVector unit{};
    unit[static_cast<std::size_t>(a.main[k])] = 1.0;
    const motion::AxisVector col = r.frames.to_mcs(unit, r.none);
    for (std::size_t rr = 0; rr < 3; ++rr) {
      const auto j = static_cast<std::size_t>(a.main[rr]);
      EXPECT_EQ(a.rot[rr][k], col[j] - shift[j]) << rr << "," << k;
    }
  }
}

TEST(ChannelFrames, MapOfShiftsIsExactlyTheMapOfItsColumns) {
  FramesRig r("mill");
  // offsets whose digits do not survive 1 + offset - offset
  r.apply_all("G92 X0.0000000000000001 Y0.00000000000000015 Z-0.0000000000000001\nM30\n");
  expect_map_as_by_columns(r);
  const AffineMap shifted = r.frames.affine(r.none);
  EXPECT_NE(shifted.rot[0][0], 1.0);  // so an identity would not pass for the map
  EXPECT_TRUE(shifted.pure_translation);
  r.apply_all("#CS ON [1][0.1,0.2,0.3,0,0,30]\nM30\n");  // and with a turn (the general way)
  expect_map_as_by_columns(r);
  EXPECT_FALSE(r.frames.affine(r.none).pure_translation);
}

TEST(ChannelFrames, RotatedCoordinateSystem) {
  FramesRig r("mill");
  r.load("G54\n#CS ON [1][20,0,0,0,0,90]\n#CS OFF\nM30\n");
  r.next();
  FrameChanges c = r.next();
  EXPECT_TRUE(c.coordinate_system_changed);
  EXPECT_TRUE(has_kind(c, frames::OffsetKind::cs));
  // PCS (10, 0) turned 90 deg -> (0, 10), + CS (20, 0) + G54 (100, 50).
  expect_xyz(r.mcs(10, 0, 0), 120, 60, -150);
  const AffineMap a = r.frames.affine(r.none);
  EXPECT_FALSE(a.pure_translation);
  EXPECT_NEAR(a.rot[0][1], -1, 1e-12);  // PCS Y -> MCS -X
  EXPECT_NEAR(a.rot[1][0], 1, 1e-12);   // PCS X -> MCS Y
  expect_xyz(a.shift, 120, 50, -150);
  expect_round_trip(r);
  r.next();
  expect_xyz(r.mcs(10, 0, 0), 110, 50, -150);
}

TEST(ChannelFrames, RotationAboutTheProgramOrigin) {
  FramesRig r("mill");
  r.load("G54\n#ROTATION ON [ANGLE=30]\n#ROTATION OFF\nM30\n");
  r.next();
  FrameChanges c = r.next();
  EXPECT_TRUE(has_kind(c, frames::OffsetKind::rotation));
  // (10, 0) turned 30 deg: (10 cos30, 10 sin30) = (8.660.., 5) + G54.
  expect_xyz(r.mcs(10, 0, 0), 100 + 10 * std::cos(M_PI / 6), 55, -150);
  expect_round_trip(r);
  r.next();
  expect_xyz(r.mcs(10, 0, 0), 110, 50, -150);
}

TEST(ChannelFrames, PsetMakesTheCurrentPositionReadTheValue) {
  FramesRig r("mill");
  r.load("G54\n#PSET X5\n#PRESET\nM30\n");
  r.next();
  // The axes stand at MCS (100, 50, -150) = PCS (0, 0, 0); #PSET X5 shifts
  // the program X by -5 so that this point reads 5.
  FrameChanges c = r.next({100, 50, -150});
  EXPECT_TRUE(has_kind(c, frames::OffsetKind::pset));
  expect_xyz(r.pcs(100, 50, -150), 5, 0, 0);
  EXPECT_DOUBLE_EQ(r.frames.values_of(frames::OffsetKind::pset, true)[0].second, -5.0);
  expect_round_trip(r);
  r.next({100, 50, -150});
  expect_xyz(r.pcs(100, 50, -150), 0, 0, 0);
}

TEST(ChannelFrames, McsOnSuspendsEveryOffsetUntilOff) {
  FramesRig r("mill");
  r.load("G54 D1\n#MCS ON\n#MCS OFF\nM30\n");
  r.next();
  r.next();
  expect_xyz(r.mcs(1, 2, 3), 1, 2, 3);
  r.next();
  expect_xyz(r.mcs(1, 2, 3), 101, 52, -47);  // + G54 + 100 mm tool on Z
}

TEST(ChannelFrames, WholeChainRoundTrips) {
  FramesRig r("mill", 1);
  r.apply_all("G54 D1\nG92 Y3\n#CS ON [1][20,10,5,0,0,35]\n#ROTATION ON [ANGLE=-20]\nM30\n");
  expect_round_trip(r);
}

TEST(ChannelFrames, LatheAxesMapToTheChainsXAndZ) {
  FramesRig r("lathe");
  EXPECT_EQ(r.frames.chain_index(0), 0);  // X
  EXPECT_EQ(r.frames.chain_index(1), 2);  // Z is the second channel axis
  r.apply_all("G18 G54 D1\nM30\n");
  // X10 + tool X25 = 35; Z-240 + G54 200 + tool Z50 = 10.
  const motion::AxisVector m = r.frames.to_mcs({10, -240}, r.none);
  EXPECT_NEAR(m[0], 35, 1e-9);
  EXPECT_NEAR(m[1], 10, 1e-9);
  const motion::AxisVector p = r.frames.to_pcs(m);
  EXPECT_NEAR(p[0], 10, 1e-9);
  EXPECT_NEAR(p[1], -240, 1e-9);
}

TEST(ChannelFrames, ChainedCoordinateSystemsAddUp) {
  FramesRig r("mill");
  // coordinates.nc without the #ACS: PART (20, 10) and HOLE (5, 5) turned
  // 90 deg on top of it. In HOLE, (10, 0) -> (0, 10) + (5, 5) = (5, 15) in
  // PART -> (25, 25) + G54 (100, 50) = (125, 75).
  r.load("G54\n#CS ADD [PART][20,10,0,0,0,0]\n#CS ADD [HOLE][5,5,0,0,0,90]\n#CS SELECT [HOLE]\n"
         "#CS SELECT [PART]\n#CS OFF ALL\nM30\n");
  r.next();
  r.next();
  r.next();
  FrameChanges c = r.next();
  EXPECT_TRUE(c.coordinate_system_changed);
  expect_xyz(r.mcs(10, 0, 0), 125, 75, -150);
  expect_round_trip(r);
  r.next();
  expect_xyz(r.mcs(0, 0, 0), 120, 60, -150);
  r.next();
  expect_xyz(r.mcs(0, 0, 0), 100, 50, -150);
}

TEST(ChannelFrames, WritingTheSelectedZeroOffsetActsAtOnce) {
  FramesRig r("mill");
  r.load("G54\nV.G.NP[1].V.X = 120\nM30\n");
  r.next();
  FrameChanges c = r.next();
  EXPECT_TRUE(has_kind(c, frames::OffsetKind::zero));
  expect_xyz(r.mcs(0, 0, 0), 120, 50, -150);
}

}  // namespace
}  // namespace nck::prep
