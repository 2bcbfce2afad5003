#pragma once
// The files of `nck run`: events (JSON lines), trace (CSV), final state (JSON).
// Each writer is opened before the run and always closed complete and valid,
// also when the program aborts.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "nck/config/machine.hpp"
#include "nck/kernel/kernel.hpp"
#include "nck/nc/decoder.hpp"
#include "nck/output/output_file.hpp"
#include "nck/output/trace_columns.hpp"
#include "nck/plc/function_text.hpp"
#include "nck/sim/dry_run.hpp"

namespace nck::app {

// What the events' JSON writers look up outside the real-time path: file
// names, spindle names, message texts, and the plan store's link and offset
// payloads (the writers beside each payload, nck/kernel/event.hpp).
struct RunNames {
  const prep::RunRecords* run = nullptr;  // a dry run, or nck-hal's records
  std::string file(std::size_t ch, std::uint16_t id) const;
  // A spindle's designation, or null.
  nlohmann::ordered_json spindle(std::optional<std::int8_t> index) const;
  // A machine axis list's name (a CiA 402 drive's event).
  nlohmann::ordered_json axis(std::int8_t index) const;
  // A diagnostic's message: its own text (Kernel::message), or the ID's text from the table.
  std::string text(ErrorId id, std::optional<std::uint32_t> message) const;
  const prep::LinkPayload& link(std::uint32_t index) const { return run->link(index); }
  const prep::OffsetPayload& offset(std::uint32_t index) const { return run->offset(index); }
};

using kernel::end_name;
using kernel::link_reason_name;
using kernel::wait_reason_name;
using plc::sync_name;
// The event kind with this "ev" name (block, wait, plc_out ...), if any.
std::optional<kernel::EventKind> event_kind_from(std::string_view name);

// JSON text that never throws (invalid UTF-8 is replaced, not an abort).
std::string dump_json(const nlohmann::ordered_json& j, int indent = -1);
// Text as a JSON string literal, the bytes dump_json gives it: made UTF-8
// (to_utf8), then '"', '\\' and control characters escaped (a report
// quotes thousands of NC lines; a JSON value for each cost ~3,000
// instructions).
std::string json_quoted(std::string_view text);

class EventWriter {
 public:
  std::optional<std::string> open(const std::string& path, bool live) { return file_.open(path, live); }
  bool is_open() const { return file_.is_open(); }
  // An event as one JSON line (without the newline).
  static std::string line(const kernel::Event& e, const RunNames& names);
  // The same event as a JSON object (the Python module's events).
  static nlohmann::ordered_json object(const kernel::Event& e, const RunNames& names);
  void write_line(const std::string& line);
  std::optional<std::string> commit() { return file_.commit(); }
  void discard() { file_.discard(); }

 private:
  OutputFile file_;
};

// Block events, the bulk of every events file (one per NC block), written
// straight as text: the same bytes as EventWriter::line (a test compares
// them) without building a JSON object per block. The file names come
// quoted from a cache (a program has few files).
class BlockEventText {
 public:
  const std::string& line(const kernel::Event& e, const RunNames& names);

 private:
  const std::string& quoted_file(std::size_t ch, std::uint16_t id, const RunNames& names);
  std::vector<std::pair<std::uint32_t, std::string>> files_;  // (channel << 16 | file id, quoted name)
  std::string line_;
};

// A trace row's values in the order of TraceWriter::column_names, each with
// the format the CSV gives it: the one walk over a cycle's output that the
// CSV file and the Python module's numpy columns share.
class TraceLayout {
 public:
  enum class Format : std::uint8_t { mm, rpm, deg, whole };  // 6, 3, 4, 0 decimals
  TraceLayout() = default;
  explicit TraceLayout(const config::Machine& m);
  // rt: f(value, format) once per column, "t" first.
  template <class F>
  void visit(const kernel::TickOutput& out, F&& f) const {
    using enum Format;
    f(out.t_s, mm);
    for (std::size_t c = 0; c < axes_per_channel_.size(); ++c)
      for (std::size_t j = 0; j < axes_per_channel_[c]; ++j) f(out.channels[c].axis_mcs[j], mm);
    for (std::size_t c = 0; c < dist_ctrl_.size(); ++c) {
      if (!dist_ctrl_[c]) continue;
      f(out.channels[c].dist_offset_mm, mm);
      f(out.channels[c].dist_sensor_mm, mm);
      f(static_cast<double>(out.channels[c].dist_state), whole);
    }
    for (std::size_t s = 0; s < speed_controlled_.size(); ++s) {
      const kernel::SpindleOutput& o = out.spindles[s];
      f(o.set_rpm, rpm);
      f(o.set_pos_deg, deg);
      f(o.act_rpm, rpm);
      if (speed_controlled_[s]) f(o.drive_output, whole);
    }
  }

 private:
  std::vector<std::size_t> axes_per_channel_;
  std::vector<bool> dist_ctrl_;  // per channel: FCT_3D_DIST_CTRL configured
  std::vector<bool> speed_controlled_;
};

// One column per path axis of every channel (MCS set point) and per spindle;
// then the --trace-columns extras per channel (path.v, path.a, path.j; 2.path.v ...).
class TraceWriter {
 public:
  std::optional<std::string> open(const std::string& path, bool live, const config::Machine& m,
                                  std::uint64_t every, TraceColumns extra = {});
  bool is_open() const { return file_.is_open(); }
  void write(std::uint64_t cycle, const kernel::TickOutput& out);
  std::optional<std::string> commit() { return file_.commit(); }
  void discard() { file_.discard(); }
  static std::vector<std::string> column_names(const config::Machine& m, TraceColumns extra = {});

 private:
  OutputFile file_;
  std::uint64_t every_ = 1;
  TraceLayout layout_;
  TraceColumns extra_{};
  std::vector<PathDerivatives> path_;  // per channel, every cycle (also between traced ones)
  std::string row_;
};

struct FinalError {
  std::uint32_t id = 0;
  std::size_t channel = 0;
  std::uint32_t line = 0;
  std::string file, msg;
};

// An entry of --final's errors (and the Python module's Run.errors,
// Run.warnings, Session.errors): its first fields {id, ch, line, file, msg},
// then the diagnostic's one shape (output/diagnostic_json.hpp).
nlohmann::ordered_json final_error_json(const FinalError& e, Severity severity = Severity::error);

// The error text when it cannot be written.
// The modal state as --final writes it ("motion": "G1", "plane": "G17" ...).
nlohmann::json modal_json(const nc::ModalState& m);

std::optional<std::string> write_final(const std::string& path, const config::Machine& m,
                                       const sim::DryRun& run, double time_s, const std::string& end_reason,
                                       const std::vector<FinalError>& errors,
                                       const nlohmann::ordered_json& time_by_cause);
// The document write_final writes (the Python module's Run.final).
nlohmann::json final_json(const config::Machine& m, const sim::DryRun& run, double time_s,
                          const std::string& end_reason, const std::vector<FinalError>& errors,
                          const nlohmann::ordered_json& time_by_cause);

}  // namespace nck::app
