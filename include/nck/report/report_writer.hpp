#pragma once
// --report FILE.html: one offline page (web/ and uPlot compiled in) showing
// the run as a CNC user reads it — backplot per channel, time plots of path
// velocity, acceleration and jerk, axes and spindle speeds (set and
// actual) with waits shaded, a 3D view with the soft-limit box,
// tables of diagnostics, events and cycle time per block and per tool.
// The data stays bounded for any run length (report_series.hpp).
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "nck/config/machine.hpp"
#include "nck/kernel/kernel.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/output/line_ledger.hpp"
#include "nck/output/trace_columns.hpp"
#include "nck/plc/hli.hpp"
#include "nck/report/backplot_axes.hpp"
#include "nck/report/report_batch.hpp"
#include "nck/report/report_contour.hpp"
#include "nck/report/report_plots.hpp"
#include "nck/report/report_series.hpp"
#include "nck/report/source_lines.hpp"

namespace nck::sim {
class DryRun;
}

namespace nck::app {

struct RunNames;
class OutputFile;

// The run's inputs as the page names them (nck run's MACHINE, PROGRAM...
// and --plc FILE).
struct ReportInputs {
  std::string machine, plc;
  std::vector<std::string> programs;
};

class ReportWriter {
 public:
  // setup: what to plot; without a start every call is a no-op.
  // `run` created (DryRunOptions::record_frames set), before the first
  // cycle: its cycle time, the axes' start positions (where each backplot
  // begins); the report watches each channel's decoded blocks from here on.
  void start(const config::Machine& m, const ReportInputs& inputs, sim::DryRun& run);
  // Once per cycle, after its events went to event().
  // `hli`: the simulated PLC's image (its overrides and feedholds are marked).
  void sample(std::uint64_t cycle, const kernel::TickOutput& out, const RunNames& names, const plc::HliImage& hli);
  // One event of the log: its type says what it is, its JSON line goes
  // into the page's event table as it is.
  void event(const kernel::Event& e, const std::string& json_line, const RunNames& names);
  // The error text when it cannot be written (the cycles not yet folded in
  // are folded first).
  std::optional<std::string> write(const std::string& path, double end_s, int exit_code);
  bool enabled() const { return enabled_; }
  // Time by cause (time_by_cause.hpp's JSON), shown as a stacked bar and
  // tables; each block row gets the page's file index ("fid") of its line.
  void set_causes(const nlohmann::ordered_json& causes);
  // nck diff --run --report: the other run (its path and times) drawn
  // beside this one (diff_command.cpp).
  void set_ghost(const nlohmann::ordered_json& ghost);

  static constexpr std::size_t kMaxTableEvents = 20000;  // non-block events in the table
  static constexpr std::size_t kMaxTableBlocks = 2000;   // block events in the table
  static constexpr std::size_t kMaxBackplotPoints = 60000;  // per channel, after thinning
  static constexpr std::size_t kMaxFrames = 1000;  // different program -> machine maps per channel
  // Lines with their cycle time: when more have run, the half with the least
  // time is dropped (a top-N table; a dropped line that runs again starts anew).
  static constexpr std::size_t kMaxBlockLines = 20000;
  // Diagnostics, waits, marks and coupling periods kept for the page; the
  // rest are counted (errors_, warnings_) or left out.
  static constexpr std::size_t kMaxListed = 20000;

 private:
  struct Accum {
    std::uint64_t count = 0;
    double time_s = 0;
  };
  struct Wait {
    std::size_t ch = 0;  // 1-based; 0: a spindle's own (spindle feedhold)
    double t0 = 0, t1 = -1;
    std::string reason, fn, spindle, sync;
    std::uint32_t line = 0;
    std::uint16_t file = 0;
  };
  struct Mark {
    double t = 0;
    std::size_t spindle = 0;
    std::size_t ch = 0;  // 1-based: a mark on the channel's velocity plot (feed override); 0: a spindle's
    std::string kind, text;
  };
  // A block's program -> machine map and whether its face-turning axis
  // reads as a diameter (G51 with display_diameter_pos): the player's DRO.
  struct Frame {
    kernel::AffineMap map;
    int diameter_slot = -1;
    bool operator==(const Frame&) const = default;
  };
  struct Channel {
    std::array<int, 3> axis{-1, -1, -1};  // channel axis index of X, Y, Z (-1: none)
    std::array<std::string, 3> axis_name;
    std::size_t axis_count = 0;  // path axes of the channel (time-plot series)
    SoftLimits limits;           // of X, Y, Z: the 3D view's box
    std::uint32_t line = 0;
    std::uint16_t file = 0;
    std::vector<std::uint16_t> file_of_id;  // decoder file id -> file_index (kNoFile: not seen yet)
    int motion = 1;   // modal G0..G3 of the block in execution
    int plane = 0;    // G17 / G18 / G19 last programmed (0: none)
    std::string tool = "-";
    Accum* block = nullptr;  // where this channel's cycles count
    Accum* tool_acc = nullptr;
    std::map<std::string, std::uint32_t> last_sync;  // fn -> sync bits of its last plc_out
    std::vector<std::size_t> open_waits;  // waits_ indices: one per spindle/function waited for
    // program -> machine maps of the blocks executed, in order of appearance
    // (PathPoint::frame); the PlanStore index of the newest
    std::vector<Frame> frames;
    std::uint32_t store_frame = kernel::kNoMessage;
    std::uint32_t frame = 0;  // index into frames of the block in execution
    // the backplot slot (0..2) of the face-turning axis a DRO shows as a
    // diameter under G51 (P-CHAN-00256 display_diameter_pos), -1: none
    int diameter_slot = -1;
    std::unique_ptr<ProgrammedContour> contour;  // G41/G42 stretches as programmed
    double feed_override_pct = 100;
    std::optional<std::size_t> hold;  // the feedhold in progress (waits_ index)
  };
  void add_path_derivative_series(std::size_t c);
  void record(std::uint64_t cycle, const kernel::TickOutput& out);
  std::unique_ptr<ReportPlots> plots_;  // tool paths, cause timelines and time series, folded on their own thread
  void add_mark(Mark m);
  std::uint16_t file_index(const std::string& name);
  static constexpr std::uint16_t kNoFile = 0xFFFF;
  std::uint16_t file_of(Channel& ch, std::size_t c, std::uint16_t id, const RunNames& names);
  const std::string& line_text(std::uint16_t file, std::uint32_t line) const;
  void take(const kernel::Event& e, const RunNames& names);
  void take_block(Channel& ch, std::size_t c, const kernel::Event& e, const RunNames& names);
  void take_output(Channel& ch, std::size_t c, const kernel::ev::PlcOut& out);
  void take_wait(Channel& ch, std::size_t c, const kernel::Event& e, const kernel::ev::Wait& wait,
                 const std::string& spindle);
  void end_wait(Channel& ch, double t_s, const kernel::ev::Wait& wait, const std::string& spindle);
  void mark_spindle(const kernel::Event& e);
  void take_frame(Channel& ch, std::uint32_t store_index, const RunNames& names);
  void watch_plc(double t_s, const plc::HliImage& hli);  // overrides and feedholds from the HLI
  std::string limits_json(const Channel& ch) const;
  std::string frames_json(const Channel& ch) const;
  std::string contour_json(const Channel& ch) const;
  void write_data(OutputFile& f, double end_s, int exit_code) const;
  void write_channels(OutputFile& f, std::vector<std::pair<std::uint16_t, std::uint32_t>>& lines_used) const;
  std::string summary_json(std::vector<std::pair<std::uint16_t, std::uint32_t>>& lines_used) const;
  std::string lines_json(const std::vector<std::pair<std::uint16_t, std::uint32_t>>& lines_used) const;
  // Synchronous operation: one row per coupling period (link events).
  struct LinkPeriod {
    int ch = 0, group = 0;
    std::string pairs;
    double on_s = 0, off_s = -1;  // -1: still enabled at the end
    std::string reason;           // why it ended
  };
  void note_link(const kernel::Event& e, const kernel::LinkEvent& link, const RunNames& names);
  std::string link_table() const;

  bool enabled_ = false;
  double cycle_s_ = 0.001;
  std::string machine_, plc_;
  std::vector<std::string> programs_;
  std::vector<Channel> channels_;
  std::vector<std::string> spindles_;
  std::vector<double> spindle_override_pct_;
  std::vector<std::optional<std::size_t>> spindle_hold_;  // waits_ index of a spindle feedhold
  std::vector<std::size_t> dist_channels_;  // channels with 3D distance control (3 series each)
  std::vector<std::string> series_meta_;  // JSON objects, in EnvelopeSeries order
  std::vector<int> decimals_;
  mutable std::vector<SourceLines> files_;  // mutable: reading a line moves the file's stream and cache
  mutable std::size_t open_files_ = 0;       // of files_ (at most 16)
  std::unordered_map<std::string, std::uint16_t> file_ids_;
  // (channel, file, line) and (channel, tool) -> cycles spent there
  // side by side (a drop reads them all), with an index; room for every
  // line kept, so a channel's block pointer stays until the next drop
  using BlockKey = std::tuple<std::size_t, std::uint16_t, std::uint32_t>;
  std::vector<std::pair<BlockKey, Accum>> blocks_;
  LineIndex block_index_;  // packed BlockKey -> blocks_[]
  static std::uint64_t packed(const BlockKey& k) {
    return static_cast<std::uint64_t>(std::get<0>(k)) << 48 | static_cast<std::uint64_t>(std::get<1>(k)) << 32 |
           std::get<2>(k);
  }
  std::uint64_t block_lines_ = 0;  // lines that ran (counted again after a drop)
  void drop_shortest_blocks();
  std::map<std::pair<std::size_t, std::string>, Accum> tools_;
  std::vector<Wait> waits_;
  std::vector<Mark> marks_;
  std::vector<std::string> diagnostics_;  // JSON lines of warnings and errors
  std::vector<std::string> events_;       // JSON lines for the event table
  std::size_t table_blocks_ = 0, events_dropped_ = 0, errors_ = 0, warnings_ = 0;
  std::string end_reason_;
  bool c_axis_used_ = false;  // a spindle was in C-axis mode (#CAX)
  std::vector<LinkPeriod> links_;
  std::string causes_json_ = "null";
  std::string ghost_json_ = "null";
  std::vector<std::pair<std::uint16_t, std::uint32_t>> cause_lines_;  // the lines its block rows show
};

}  // namespace nck::app
