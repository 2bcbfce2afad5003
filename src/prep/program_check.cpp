// The pre-flight check of a channel's program; see program_check.hpp. It
// strings the stages together as ChannelPrep does for a run, but records a
// failure where ChannelPrep would hand the kernel an error and stop.
#include "nck/prep/program_check.hpp"

#include "nck/prep/assumed_feedback.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include "nck/kernel/queues.hpp"
#include "nck/nc/decoder.hpp"
#include "nck/plc/hli.hpp"
#include "nck/prep/assumed_feedback.hpp"
#include "nck/prep/channel_prep.hpp"
#include "nck/prep/decoder_setup.hpp"
#include "nck/prep/error_command.hpp"
#include "nck/prep/lookahead_window.hpp"
#include "nck/prep/path_preview.hpp"
#include "nck/prep/planner.hpp"
#include "nck/prep/radius_comp.hpp"
#include "spindle_limit_check.hpp"

namespace nck::prep {
namespace {

nc::DecoderConfig lint_config(const config::Machine& m, std::size_t ch, const ProgramCheckOptions& o) {
  nc::DecoderConfig cfg = decoder_config(m, ch);
  cfg.continue_after_error = true;  // a bad block is dropped, the next one decoded
  cfg.stop = o.stop;
  return cfg;
}

class ChannelCheck {
 public:
  ChannelCheck(const config::Machine& m, std::size_t ch, const std::filesystem::path& program,
               const ProgramCheckOptions& o)
      : planner_(m, ch, store_, PlannerOptions{o.clamp_index}, kernel_spindles(m, ch)),
        window_(std::min<std::size_t>(m.channels[ch].lookahead_blocks, kernel::kMaxLookAheadDepth),
                m.cycle_time_us * 1e-6),
        trc_(m, ch),
        spindle_limits_(m, ch, kernel_spindles(m, ch)),
        queue_(std::make_unique<kernel::CommandQueue>()),
        decoder_(program, lint_config(m, ch, o)),
        preview_(o.preview) {
    window_.set_blend_axes(planner_.blend_axes());
    decoder_.set_kernel_state_reader(&planner_);
    for (const auto& [name, value] : initial_variables(m, ch, o.clamp_index)) (void)decoder_.set_variable(name, value);
  }

  ProgramCheckResult run();

 private:
  void take_decoder_diagnostics();
  void prepare(const nc::Block& b);
  // What execution would report back, taken as "nothing changed".
  // The errors and warnings a planned command would raise in a run.
  void record(const PlannedCommand& c);
  void add(Diagnostic d);
  void to_window(const PlannedBlock& planned, bool flush);
  void release(bool flush);
  std::string message(std::optional<std::uint32_t> index) const;

  PlanStore store_;  // before the planner, which keeps a reference to it
  Planner planner_;
  LookAheadWindow window_;
  RadiusComp trc_;
  SpindleLimitCheck spindle_limits_;
  std::vector<Diagnostic> spindle_found_;
  std::unique_ptr<kernel::CommandQueue> queue_;  // what the window releases; emptied at once
  nc::Decoder decoder_;
  std::vector<TrcOut> outs_;
  std::set<std::tuple<std::uint32_t, std::string, std::uint32_t>> reported_;  // id, file, line
  std::size_t decoder_seen_ = 0;
  std::uint32_t last_main_line_ = 0;  // of the main program's last block decoded
  ProgramCheckResult result_;
  PathPreview* preview_;  // null: a lint only
};

ProgramCheckResult ChannelCheck::run() {
  for (;;) {
    nc::Decoder::Result r = decoder_.next();
    take_decoder_diagnostics();
    if (r.status == nc::Decoder::Status::stopped) {
      result_.stopped = true;
      break;
    }
    if (r.status == nc::Decoder::Status::error) {
      if (decoder_.can_continue()) continue;  // the bad block is dropped
      break;
    }
    if (r.status == nc::Decoder::Status::end) {
      // As the run raises it: at the main program's last block.
      add(make_diagnostic(ErrorId::KernelMissingProgramEnd, {decoder_.file_name(0), last_main_line_, 0},
                          "the program has no M30 (or M2) at its end"));
      break;
    }
    ++result_.blocks;
    if (r.block.depth == 0) last_main_line_ = r.block.line;
    prepare(r.block);
    if (ChannelPrep::needs_feedback(r.block)) take_feedback(assumed_feedback(r.block, planner_), planner_, decoder_);
    if (r.block.program_end || (preview_ && preview_->full())) break;
  }
  return std::move(result_);
}

void ChannelCheck::take_decoder_diagnostics() {
  const std::vector<Diagnostic>& ds = decoder_.diagnostics();
  for (; decoder_seen_ < ds.size(); ++decoder_seen_) add(ds[decoder_seen_]);
}

// Compensation, planning and the window, as ChannelPrep::prepare; a command
// that fails leaves the window out (in a run nothing after it would run).
void ChannelCheck::prepare(const nc::Block& b) {
  outs_.clear();
  trc_.push(b, planner_, outs_);
  const bool flush = ChannelPrep::needs_feedback(b) || b.program_end;
  for (const TrcOut& o : outs_) {
    if (o.error) {
      record(error_command(*o.error, o.block.file_id, store_));
      continue;
    }
    const PlannedBlock planned = planner_.plan(o.block);
    bool failed = false;
    for (const PlannedCommand& c : planned) {
      record(c);
      failed = failed || c.kind == CommandKind::error;
    }
    if (!failed) to_window(planned, flush);
  }
}


void ChannelCheck::record(const PlannedCommand& c) {
  const std::string& file = decoder_.file_name(c.head.file_id);
  c.each<kernel::Warning>([&](const kernel::Warning& w) {
    add(Diagnostic{w.id, Severity::warning, {file, c.head.line, 0}, message(w.message)});
  });
  if (const auto* error = std::get_if<kernel::Error>(&c.step); error && c.kind == CommandKind::error) {
    add(Diagnostic{error->id, Severity::error, {file, c.head.line, 0}, message(error->message)});
    return;
  }
  if (preview_ && c.kind == CommandKind::motion)
    preview_->add(c.segment, c.head.file_id, c.head.line, planner_.modal().motion == nc::Motion::rapid,
                  [&](const motion::AxisVector& mcs) { return planner_.frames().to_pcs(planner_.cartesian(mcs)); });
  spindle_found_.clear();
  spindle_limits_.check(c, spindle_found_);
  for (Diagnostic& d : spindle_found_) {
    d.loc.file = file;
    add(std::move(d));
  }
}

void ChannelCheck::add(Diagnostic d) {
  if (reported_.emplace(number(d.id), d.loc.file, d.loc.line).second) result_.diagnostics.push_back(std::move(d));
}

void ChannelCheck::to_window(const PlannedBlock& planned, bool flush) {
  if (!window_.has_room()) release(false);
  (void)window_.push(planned);
  release(flush);
}

// Releases what may leave the window; the queue is emptied as it fills.
void ChannelCheck::release(bool flush) {
  for (;;) {
    const bool all = window_.release(*queue_, flush);
    while (!queue_->empty()) queue_->pop();
    if (all) return;
  }
}

std::string ChannelCheck::message(std::optional<std::uint32_t> index) const {
  return index && *index < store_.messages.size() ? store_.messages[*index] : std::string();
}

}  // namespace

ProgramCheckResult check_program(const config::Machine& m, std::size_t ch, const std::filesystem::path& program,
                                 const ProgramCheckOptions& options) {
  // The planner and the window are large: on the heap, not the stack.
  auto check = std::make_unique<ChannelCheck>(m, ch, program, options);
  return check->run();
}

}  // namespace nck::prep
