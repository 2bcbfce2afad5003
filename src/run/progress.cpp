#include "nck/run/progress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace nck::app {
namespace {

std::uint32_t count_lines(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  const auto n = std::count(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>(), '\n');
  return static_cast<std::uint32_t>(n + 1);  // the last line may have no '\n'
}

std::string clock_text(double s) {
  const auto total = static_cast<long>(s + 0.5);
  return total >= 3600 ? fmt::format("{}:{:02}:{:02}", total / 3600, total / 60 % 60, total % 60)
                       : fmt::format("{}:{:02}", total / 60, total % 60);
}

}  // namespace

Progress::Progress(bool enabled, const std::vector<std::string>& programs)
    : enabled_(enabled && isatty(fileno(stderr))), start_(std::chrono::steady_clock::now()) {
  if (!enabled_) return;
  for (const std::string& p : programs) channels_.push_back(Channel{p.empty() ? 0 : count_lines(p)});
}

void Progress::take(const kernel::TickOutput& o) {
  if (!enabled_) return;
  for (const kernel::Event& e : o.events) {
    // file 0 is the channel's main program; a subroutine keeps its caller's place.
    if (e.kind() != kernel::EventKind::block || e.at.file_id != 0 || e.channel == 0) continue;
    if (e.channel > channels_.size()) continue;
    Channel& c = channels_[e.channel - 1u];
    c.line = e.at.line;
    c.has_n = e.at.n.has_value();
    c.n = e.at.n.value_or(0);
  }
}

double Progress::fraction() const {
  double sum = 0;
  std::size_t n = 0;
  for (const Channel& c : channels_)
    if (c.lines > 0) sum += std::min(1.0, static_cast<double>(c.line) / c.lines), ++n;
  return n == 0 ? 0 : sum / static_cast<double>(n);
}

void Progress::update(double t_s) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(200)) return;
  last_ = now;
  const double wall_s = std::chrono::duration<double>(now - start_).count();
  const double f = fraction();
  std::string where;
  if (!channels_.empty()) {
    const Channel& c = channels_.front();
    where = c.has_n ? fmt::format(" N{} line {}", c.n, c.line) : fmt::format(" line {}", c.line);
  }
  // The time left from the pace so far; unknown until a little of the program has run.
  const std::string eta = f > 0.01 && f < 1 ? clock_text(wall_s * (1 - f) / f) : "--:--";
  fmt::print(stderr, "\r\033[Knck: {:3.0f}%{} | {:.1f} s simulated, {:.0f}x real time | ETA {}", 100 * f, where,
             t_s, wall_s > 0 ? t_s / wall_s : 0.0, eta);
  shown_ = true;
}

void Progress::clear() {
  if (!shown_) return;
  fmt::print(stderr, "\r\033[K");
  shown_ = false;
}

}  // namespace nck::app
