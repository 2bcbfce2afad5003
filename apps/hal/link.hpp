#pragma once
// The shared-memory segment between nck-hal (userspace: machine folder,
// decoder, preparation) and the real-time module nck.so (the kernel's
// cycle in a HAL thread). Pointer-free and of fixed size: the two processes
// map it at different addresses (docs/decisions.md, "HAL: two components").
//
// nck-hal creates it (rtapi_shmem_new with kLinkKey), writes the machine's
// lists as a text pack and then feeds the command queues; nck.so, loaded
// after it, builds its kernel from the pack in its load function (never in
// the thread) and relays commands into it every cycle. With nck-hal
// --serve, nck.cycle also publishes its state every cycle and takes the
// operator's actions from the API.
#include <atomic>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>

#include "nck/config/machine.hpp"
#include "nck/core/spsc_queue.hpp"
#include "nck/core/triple_buffer.hpp"
#include "nck/kernel/event.hpp"
#include "nck/kernel/queues.hpp"
#include "nck/run/live_snapshot.hpp"
#include "nck/sim/scenario_action.hpp"

namespace nck::hal {

inline constexpr int kLinkKey = 0x4E434B31;  // "NCK1"
inline constexpr std::uint32_t kLinkMagic = 0x6E636B68;
inline constexpr std::uint32_t kLinkVersion = 2;
inline constexpr std::size_t kMachinePackBytes = 1u << 20;
inline constexpr std::size_t kEventRingLength = 4096;
inline constexpr std::size_t kApiActionSlots = 64;

enum class RtState : std::uint32_t { absent = 0, configured = 1, running = 2, error = 3 };

struct Link {
  std::uint32_t magic = 0;
  std::uint32_t version = 0;
  std::atomic<std::uint32_t> pack_bytes{0};  // set last by nck-hal: the pack is complete
  std::atomic<std::uint32_t> rt_state{0};    // RtState, written by nck.so
  std::atomic<std::uint32_t> rt_error_id{0};
  std::atomic<std::uint32_t> events_dropped{0};
  std::atomic<std::uint64_t> cycles{0};
  std::atomic<std::uint8_t> channel_done[config::kMaxChannels]{};
  kernel::CommandQueue commands[config::kMaxChannels];
  kernel::FeedbackQueue feedback[config::kMaxChannels];
  SpscQueue<kernel::Event, kEventRingLength> events;  // nck.so -> nck-hal
  // nck-hal --serve: set before nck.so is loaded; nck.cycle then publishes
  // its state after every cycle and takes the API's operator actions.
  std::atomic<std::uint32_t> serving{0};
  TripleBuffer<app::LiveSnapshot> state;                        // nck.so -> nck-hal
  SpscQueue<sim::ScenarioAction, kApiActionSlots> api_actions;  // nck-hal -> nck.so
  // Per channel, the skip levels in force (nck.channel.N.skip-mask or the
  // API's): nck-hal's preparation decodes with them (/1 = bit 0).
  std::atomic<std::uint32_t> skip_mask[config::kMaxChannels]{};
  char pack[kMachinePackBytes];  // records: u32 name length, u32 text length, name, text
};
static_assert(std::is_trivially_copyable_v<kernel::Event>, "events cross the process boundary by copy");
static_assert(std::is_trivially_copyable_v<sim::ScenarioAction>, "actions cross the process boundary by copy");
static_assert(std::atomic<std::uint64_t>::is_always_lock_free, "lock-free across processes");

// The machine's lists by path, as load_machine(…, {.read_text}) asks for them.
using ListPack = std::map<std::string, std::string>;

// Writes `lists` into link.pack; false when they do not fit.
inline bool write_pack(Link& link, const ListPack& lists) {
  std::size_t at = 0;
  for (const auto& [name, text] : lists) {
    const std::size_t need = 8 + name.size() + text.size();
    if (at + need > sizeof link.pack) return false;
    const auto n = static_cast<std::uint32_t>(name.size()), t = static_cast<std::uint32_t>(text.size());
    std::memcpy(link.pack + at, &n, 4);
    std::memcpy(link.pack + at + 4, &t, 4);
    std::memcpy(link.pack + at + 8, name.data(), name.size());
    std::memcpy(link.pack + at + 8 + name.size(), text.data(), text.size());
    at += need;
  }
  link.pack_bytes.store(static_cast<std::uint32_t>(at), std::memory_order_release);
  return true;
}

// Reads the pack back (bounds checked: a torn pack gives fewer lists, never a crash).
inline ListPack read_pack(const Link& link) {
  ListPack out;
  const std::size_t end = std::min<std::size_t>(link.pack_bytes.load(std::memory_order_acquire), sizeof link.pack);
  std::size_t at = 0;
  while (at + 8 <= end) {
    std::uint32_t n = 0, t = 0;
    std::memcpy(&n, link.pack + at, 4);
    std::memcpy(&t, link.pack + at + 4, 4);
    if (at + 8 + std::size_t{n} + t > end) break;
    out.emplace(std::string(link.pack + at + 8, n), std::string(link.pack + at + 8 + n, t));
    at += 8 + std::size_t{n} + t;
  }
  return out;
}

}  // namespace nck::hal
