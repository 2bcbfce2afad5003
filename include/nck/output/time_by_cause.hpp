#pragma once
// Time by cause (issue 31): every cycle of every busy channel goes to
// exactly one class — at feed, an axis's velocity (which axis), accelerating
// or braking (which axis binds), a corner or transition, the override,
// rapid, a wait (with its reason), a hold, starved preparation. The kernel
// names the class per cycle (ChannelOutput::cause, a few comparisons in the
// path unit); this ledger, outside the cycle, names the binding axis from
// the set points and sums cycles per block (NC line), tool, file and cause.
// Sums are whole cycles, so the classes add up to the channel's time exactly.
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "nck/config/machine.hpp"
#include "nck/core/kept_quotient.hpp"
#include "nck/core/shown_number.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/output/block_identity.hpp"
#include "nck/output/line_ledger.hpp"

namespace nck::app {

struct RunNames;

// A class: the kernel's cause and its detail (axis index, wait reason,
// hold kind; -1: none).
struct CauseClass {
  kernel::CycleCause cause = kernel::CycleCause::none;
  std::int16_t detail = -1;
  bool operator==(const CauseClass&) const = default;
};
// Cycles per class, a handful per block: the first few kept in place, so
// a line run for the first time allocates nothing (200,000 lines of a
// long program would be as many allocations and frees). Entries keep
// the order add() gives them: the hit moves to the front, so the next
// cycle's class usually is the first compared.
class CauseTally {
 public:
  using Entry = std::pair<CauseClass, std::uint64_t>;
  void add(CauseClass c, std::uint64_t cycles);
  std::size_t size() const { return near_count_ + far_.size(); }
  const Entry& operator[](std::size_t i) const { return i < kNear ? near_[i] : far_[i - kNear]; }
  std::uint64_t cycles() const;
  // The entries by cycles, most first (equal counts in their order).
  std::vector<Entry> sorted() const;

 private:
  static constexpr std::size_t kNear = 4;
  Entry& at(std::size_t i) { return i < kNear ? near_[i] : far_[i - kNear]; }
  std::array<Entry, kNear> near_{};
  std::uint8_t near_count_ = 0;
  std::vector<Entry> far_;  // beyond the first kNear
};

class TimeByCause {
 public:
  // The most time-losing blocks --final lists per channel.
  static constexpr std::size_t kMaxBlocks = 2000;
  // Lines kept per channel: beyond, the half that lost the least time is
  // dropped (memory stays bounded for any program; a dropped line that
  // runs again starts anew). The sums per cause, tool and file stay exact.
  static constexpr std::size_t kMaxLines = 20000;

  // setup: the channels' axes (names and dynamics) and the cycle time.
  // by_line false: only the channels' totals are kept (top_lines(); json()
  // then has no tools, subroutines or blocks), for runs whose outputs show
  // no more.
  void start(const config::Machine& m, double cycle_s, bool by_line = true);
  // Once per cycle, after the kernel's tick. rt-ish: it allocates for a
  // new tool or file, a line with more than four classes, and now and then
  // for the index's pool.
  void take(const kernel::TickOutput& out, const RunNames& names);
  // After the last cycle, before json() and top_lines().
  void finish();
  // --final's "time_by_cause".
  nlohmann::ordered_json json() const;
  // The three causes with the most time, one line each, for stderr.
  std::vector<std::string> top_lines(std::size_t count = 3) const;

  using Class = CauseClass;
  using Tally = CauseTally;

 private:
  struct Block {
    std::uint16_t file = 0;
    std::uint32_t line = 0;
    bool has_n = false;
    std::int64_t n = 0;
    std::uint64_t runs = 0;
    double length_mm = 0, ideal_s = 0;  // travelled, and its length / feed
    Tally tally;
    std::uint64_t cycles = 0;  // of the tally: asked for by each drop of the lines that lost least
  };
  struct Channel {
    std::vector<std::string> axis_names;
    std::vector<double> v_max, a_acc, a_dec;  // feed dynamics per axis
    std::vector<double> last_mcs;
    int c_axis = -1;  // the spindle's C axis: it shows the turning spindle outside #CAX
    Block* block = nullptr;
    std::string tool = "-";
    std::uint16_t file = 0;
    std::vector<Block> blocks;  // the lines kept, at most kMaxLines + 1
    LineIndex block_index;  // key_of(file, line) -> blocks[]
    std::unordered_map<std::string, Tally> tools;
    std::unordered_map<std::uint16_t, Tally> files;
    Tally* tool_tally = nullptr;  // tools[tool], files[file]: where cycles count now
    Tally* file_tally = nullptr;
    std::vector<std::string> file_names;
    Tally total;
    std::uint64_t cycles = 0;
    // Cycles of one class in a row, not yet added to the tallies (a run
    // ends when the class, block, tool or file changes).
    Class run{};
    std::uint64_t run_cycles = 0;
    KeptQuotient ideal_step_s;  // a cycle's length / feed: at a steady feed the same
  };
  static std::uint64_t key_of(std::uint16_t file, std::uint32_t line) {
    return static_cast<std::uint64_t>(file) << 32 | line;
  }
  void take_event(const kernel::Event& e, const RunNames& names);
  void flush(Channel& ch);
  void flush_lines(Channel& ch);
  double lost_s(const Block& b) const;
  void drop_least_lost(Channel& ch);
  Class classify(Channel& ch, const kernel::ChannelOutput& o) const;
  std::string class_name(const Channel& ch, Class c) const;
  nlohmann::ordered_json tally_json(const Channel& ch, const Tally& t) const;
  nlohmann::ordered_json channel_json(const Channel& ch) const;
  nlohmann::ordered_json blocks_json(const Channel& ch) const;
  std::vector<BlockIdentity> identities(const Channel& ch, const std::vector<const Block*>& blocks) const;

  // n cycles in seconds, from the whole-µs cycle time (0.018, not 0.018000000000000002)
  double seconds(std::uint64_t n) const { return static_cast<double>(n) * static_cast<double>(cycle_us_) / 1e6; }
  double written_seconds(std::uint64_t n) const { return written(seconds(n)); }  // in the JSON

  std::vector<Channel> channels_;
  bool by_line_ = true;
  double cycle_s_ = 0.001;
  std::int64_t cycle_us_ = 1000;
};

// "feed", "axis_velocity", ... as --final names the kernel's causes.
const char* cause_name(kernel::CycleCause c);

}  // namespace nck::app
