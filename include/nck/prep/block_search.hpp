#pragma once
// Block search (TF5200 block search types 1, 3 and 4): the program is
// decoded and planned from its start without motion up to a restart mark,
// so that modal state, offsets, tool, variables, subroutine and loop levels
// are those of a full run there; the technology functions met on the way
// are collected, handed to the PLC before the restart, and the axes return
// to the contour in a rapid straight line (docs/operating.md).
//
// This file holds the mark (where to restart) and what is collected; the
// channel's preparation (channel_prep.cpp) runs the search.
#include <cstdint>
#include <expected>
#include <optional>
#include <string>
#include <vector>

#include "nck/kernel/attachment.hpp"
#include "nck/nc/block.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/prep/lookahead_window.hpp"
#include "nck/prep/planned_command.hpp"
#include "nck/prep/search_mark.hpp"

namespace nck::prep {

// Technology functions met in search, the last of each kind: a spindle's
// last rotation, stop or position (with its last speed), its other
// settings, the last T, and the last of each M and H function, in the order
// they were last met.
class SearchCollector {
 public:
  void take(const PlannedCommand& c);
  // Nop commands carrying what was collected, for the restart.
  std::vector<PlannedCommand> commands(const PlannedCommand& like) const;
  std::size_t size() const { return outputs_.size() + actions_.size(); }

 private:
  void take(const kernel::Output& o);
  void take(const kernel::SpindleAction& a);

  std::vector<kernel::Output> outputs_;
  std::vector<kernel::SpindleAction> actions_;
};

// Decides, block by block as they are decoded, where the search ends.
class SearchMatcher {
 public:
  explicit SearchMatcher(const SearchMark& mark) : mark_(mark) {}
  // Is b (decoded from `file`, its path) the restart block?
  bool is_mark(const nc::Block& b, const std::string& file);
  // A block with the mark's N was met at all (type 4: else a warning).
  bool number_seen() const { return seen_ > 0; }
  const SearchMark& mark() const { return mark_; }

 private:
  bool in_program(const nc::Block& b, const std::string& file) const;

  SearchMark mark_;
  std::uint32_t seen_ = 0;  // passes over the mark so far
};

class Planner;

// One search, from the program start to the restart: ChannelPrep hands it
// every decoded block and every planned block until it restarts.
class SearchRun {
 public:
  // start_mcs: where the axes stand while the program is searched.
  SearchRun(const SearchMark& mark, const motion::AxisVector& start_mcs) : matcher_(mark), start_mcs_(start_mcs) {}

  // A block was decoded from `file`: is it the mark?
  void decoded(const nc::Block& b, const std::string& file) {
    if (!mark_row_ && matcher_.is_mark(b, file)) mark_row_ = b.row;
  }
  // Do the commands planned from b begin the real run? (With tool radius
  // compensation a block's commands come out a block later.)
  bool restarts_at(const nc::Block& b) const { return mark_row_ && b.row >= *mark_row_; }
  // Commands planned in search: their functions are collected, nothing runs.
  void searched(const PlannedBlock& planned) {
    for (const PlannedCommand& c : planned) collected_.take(c);
  }
  // The restart, from the commands planned for the mark block: the
  // collected functions, the return to the contour, then the mark block
  // (its functions collected too when it moves, its motion from the covered
  // share on). An error when the restart cannot be made.
  std::expected<std::vector<PlannedBlock>, Diagnostic> restart(PlannedBlock planned, const Planner& planner,
                                                               const SourceLoc& at);
  // The program ended before the mark: what to report (a warning when its
  // block number never came, then error 20704).
  std::vector<Diagnostic> not_found(const SourceLoc& at) const;
  // The first command a searching channel gets: it enters `searching`.
  static PlannedCommand begins();

 private:
  SearchMatcher matcher_;
  SearchCollector collected_;
  motion::AxisVector start_mcs_{};
  std::optional<std::uint64_t> mark_row_;
};

}  // namespace nck::prep
