#include "nck/sim/plc_sim.hpp"

#include <algorithm>
#include <cmath>

namespace nck::sim {

using plc::is_gear_function;
using plc::kMaxHliChannels;
using plc::kNoSpindle;
using plc::TechKind;
namespace {

// Delays in sim.lis are given in ms and converted to s; comparing at
// nanosecond resolution keeps "exact to the cycle" immune to rounding.
constexpr double kTimeEps_s = 1e-9;

double non_negative(double v) { return std::isfinite(v) && v > 0 ? v : 0.0; }

bool is_spindle_m(std::int32_t n) { return n == 3 || n == 4 || n == 5 || n == 19; }

bool spindle_in_range(std::uint8_t ch, std::int8_t sp) {
  return ch >= 1 && ch <= kMaxHliChannels && sp >= 0 &&
         static_cast<std::size_t>(sp) < config::kMaxSpindles;
}

}  // namespace

PlcSim::PlcSim(const config::SimConfig& sim) {
  m_delay_s_.fill(-1.0);
  for (const auto& [m, delay_s] : sim.m_ack_delay_s)
    if (m < kMaxMNumber) m_delay_s_[m] = non_negative(delay_s);
  default_delay_s_ = non_negative(sim.plc_ack_delay_s);
  spindle_delay_s_ = non_negative(sim.spindle_ack_delay_s);
  tool_delay_s_ = non_negative(sim.tool_change_time_s);
  gear_delay_s_ = non_negative(sim.gear_change_time_s);
}

void PlcSim::set_free_gear_functions(std::uint8_t ch) noexcept {
  if (ch >= 1 && ch <= free_gear_.size()) free_gear_[ch - 1] = true;
}

bool PlcSim::shifts_gear(const TechOutput& out) const noexcept {
  const bool free = out.channel >= 1 && out.channel <= free_gear_.size() && free_gear_[out.channel - 1];
  return is_gear_function(out) && !free;
}

double PlcSim::ack_delay_s(const TechOutput& out) const noexcept {
  switch (out.kind) {
    case TechKind::s: return spindle_delay_s_;
    case TechKind::t: return tool_delay_s_;
    case TechKind::h: return default_delay_s_;
    case TechKind::m:
    case TechKind::none: break;
  }
  // A delay configured for this very M number wins over the generic ones.
  if (out.number >= 0 && static_cast<std::size_t>(out.number) < kMaxMNumber &&
      m_delay_s_[static_cast<std::size_t>(out.number)] >= 0)
    return m_delay_s_[static_cast<std::size_t>(out.number)];
  if (shifts_gear(out)) return gear_delay_s_;
  if (out.number == 6) return tool_delay_s_;
  if (is_spindle_m(out.number) && out.spindle != kNoSpindle) return spindle_delay_s_;
  return default_delay_s_;
}

bool PlcSim::submit(OutputHandle h, const TechOutput& out, double now_s) noexcept {
  if (h == kNoHandle) return false;
  for (auto& s : slots_) {
    if (s.handle != kNoHandle) continue;
    s.handle = h;
    ++used_;
    s.output = out;
    s.due_s = (std::isfinite(now_s) ? now_s : 0.0) + ack_delay_s(out);
    s.acked = false;
    s.t_ack_s = 0;
    return true;
  }
  return false;
}

void PlcSim::tick(double now_s) noexcept {
  if (silent_ || used_ == acked_) return;  // nothing waits: no slot to look at
  for (auto& s : slots_) {
    if (s.handle == kNoHandle || s.acked) continue;
    if (now_s + kTimeEps_s >= s.due_s) {
      s.acked = true;
      ++acked_;
      s.t_ack_s = now_s;
      on_ack(s);
    }
  }
}

void PlcSim::on_ack(const Slot& s) noexcept {
  if (!shifts_gear(s.output) || !spindle_in_range(s.output.channel, s.output.spindle)) return;
  gear_[s.output.channel - 1][static_cast<std::size_t>(s.output.spindle)] =
      static_cast<std::uint8_t>(s.output.number - 39);
}

PlcSim::Slot* PlcSim::find(OutputHandle h) noexcept {
  if (h == kNoHandle) return nullptr;
  for (auto& s : slots_)
    if (s.handle == h) return &s;
  return nullptr;
}

const PlcSim::Slot* PlcSim::find(OutputHandle h) const noexcept {
  return const_cast<PlcSim*>(this)->find(h);
}

bool PlcSim::acknowledged(OutputHandle h) const noexcept {
  const Slot* s = find(h);
  return s != nullptr && s->acked;
}

bool PlcSim::pending(OutputHandle h) const noexcept {
  const Slot* s = find(h);
  return s != nullptr && !s->acked;
}

void PlcSim::release(OutputHandle h) noexcept {
  if (Slot* s = find(h)) free_slot(*s);
}

void PlcSim::free_slot(Slot& s) noexcept {
  --used_;
  if (s.acked) --acked_;
  s = Slot{};
}

std::size_t PlcSim::drain_acks(AckList& out) noexcept {
  out.clear();
  if (acked_ == 0) return 0;
  // Oldest first: handles grow with submission order (wrap-around aside).
  while (true) {
    Slot* oldest = nullptr;
    for (auto& s : slots_)
      if (s.handle != kNoHandle && s.acked && (oldest == nullptr || s.handle < oldest->handle))
        oldest = &s;
    if (oldest == nullptr) break;
    out.push_back(PlcAck{oldest->handle, oldest->output, oldest->t_ack_s});
    free_slot(*oldest);
  }
  return out.size();
}

void PlcSim::clear() noexcept {
  used_ = acked_ = 0;
  for (auto& s : slots_) s = Slot{};
}

std::uint8_t PlcSim::gear_stage(std::uint8_t ch, std::int8_t spindle) const noexcept {
  if (!spindle_in_range(ch, spindle)) return 0;
  return gear_[ch - 1][static_cast<std::size_t>(spindle)];
}

bool PlcSim::gear_changing(std::uint8_t ch, std::int8_t spindle) const noexcept {
  return std::any_of(slots_.begin(), slots_.end(), [&](const Slot& s) {
    return s.handle != kNoHandle && !s.acked && shifts_gear(s.output) &&
           s.output.channel == ch && s.output.spindle == spindle;
  });
}

std::size_t PlcSim::waiting() const noexcept {
  return static_cast<std::size_t>(std::count_if(
      slots_.begin(), slots_.end(), [](const Slot& s) { return s.handle != kNoHandle && !s.acked; }));
}

}  // namespace nck::sim
