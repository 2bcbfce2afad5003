#pragma once
// External spindle commands (TF5200 HLI ext_to_ipo; FCT-S1 §2.9): the PLC hands
// the CNC spindle jobs past the NC program. They run in order of arrival
// (per spindle), and the CNC acknowledges each one when it has completed it
// (speed reached, standstill, in position).
//
// Real-time contract: fixed capacity, no heap, noexcept.
#include <array>
#include <cstddef>
#include <cstdint>

#include "nck/core/ring_buffer.hpp"
#include "nck/plc/hli.hpp"

namespace nck::plc {

// The spindle M function of an external command (M3/M4/M5/M19).
enum class ExtFunction : std::uint8_t { m3 = 3, m4 = 4, m5 = 5, m19 = 19 };

inline constexpr std::size_t kSpindleNameChars = 16;  // including the terminating 0

struct ExtSpindleCommand {
  std::uint32_t seq = 0;            // arrival number, assigned by push (1, 2, ...)
  std::uint8_t channel = 1;         // 1-based
  std::array<char, kSpindleNameChars> spindle_name{};  // as written, e.g. "S2"
  std::int8_t spindle = kNoSpindle; // index into the channel's spindles (resolved)
  ExtFunction fn = ExtFunction::m5;
  bool has_rev = false;
  double rev_rpm = 0;               // REV, >= 0
  bool has_pos = false;
  double pos_deg = 0;               // POS (M19 only)
};

class ExtCommandQueue {
 public:
  static constexpr std::size_t kCapacity = 16;   // commands not yet taken
  static constexpr std::size_t kAckHistory = 64; // acknowledgements remembered

  // rt: enqueue; returns the arrival number, or 0 when full (report
  // PlcExtCommandQueueFull; the command is dropped).
  std::uint32_t push(ExtSpindleCommand cmd) noexcept;
  // rt: the CNC takes the oldest command; false when there is none.
  bool pop(ExtSpindleCommand& out) noexcept;
  // rt: the oldest command, not taken; only when !empty().
  const ExtSpindleCommand& front() const noexcept { return queue_.front(); }
  bool empty() const noexcept { return queue_.empty(); }
  std::size_t size() const noexcept { return queue_.size(); }

  // rt: the CNC has completed command seq.
  void acknowledge(std::uint32_t seq) noexcept;
  // rt: true when seq is among the last kAckHistory acknowledgements.
  bool acknowledged(std::uint32_t seq) const noexcept;
  // rt: the newest acknowledged arrival number (0 = none yet).
  std::uint32_t last_acknowledged() const noexcept { return last_ack_; }

  void clear() noexcept;  // rt: drops waiting commands (CNC reset); history stays

 private:
  RingBuffer<ExtSpindleCommand, kCapacity> queue_;
  RingBuffer<std::uint32_t, kAckHistory> acks_;
  std::uint32_t next_seq_ = 1;
  std::uint32_t last_ack_ = 0;
};

}  // namespace nck::plc
