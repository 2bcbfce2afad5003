// nck-hal: the userspace half of nck in HAL (loadusr -W nck-hal MACHINE PROGRAM).
// Runs as the invoking user: reads the machine folder and the program, packs
// the machine's lists into the shared segment for loadrt nck, then decodes
// and prepares the program into the shared command queues while nck.cycle
// runs it, and prints the kernel's events. Ends when the channel is done,
// the real-time side reports an error, or on SIGTERM (halcmd unloadusr).
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <thread>

#include <fmt/format.h>

#include "hal.h"
#include "rtapi.h"

#include "hal/link.hpp"
#include "nck/config/list_reader.hpp"
#include "nck/config/load.hpp"
#include "nck/prep/channel_prep.hpp"
#include "nck/prep/plan_store.hpp"

namespace {

std::atomic<bool> stop_requested{false};
void on_signal(int) { stop_requested = true; }

int fail(nck::ErrorId id, const std::string& what) {
  std::fprintf(stderr, "nck-hal: error %u: %s\n", static_cast<unsigned>(id), what.c_str());
  return 1;
}

// One event as a line: its kind, and what a commissioning engineer needs
// of a wait (the reason), of an error or warning (the ID, the axis) and of
// a drive's mode (the axis, the mode).
void print_event(const nck::kernel::Event& e, const nck::config::Machine& m) {
  std::string what = nck::kernel::event_name(e.kind());
  if (const auto* w = e.get<nck::kernel::ev::Wait>()) what = fmt::format("wait reason={}", nck::kernel::wait_reason_name(w->reason));
  const nck::kernel::ev::Diagnosis* d = e.get<nck::kernel::ev::Error>();
  if (!d) d = e.get<nck::kernel::ev::Warning>();
  if (d) {
    what += fmt::format(" id={}", static_cast<unsigned>(d->id));
    if (d->axis && *d->axis >= 0) what += " axis=" + nck::config::axis_list_name(m, static_cast<std::size_t>(*d->axis));
  }
  if (const auto* dr = e.get<nck::drives::DriveEvent>(); dr && dr->axis >= 0)
    what += fmt::format(" axis={} mode={}", nck::config::axis_list_name(m, static_cast<std::size_t>(dr->axis)),
                        nck::drives::mode_short_name(dr->mode));
  std::printf("event t=%.4f ch=%u line=%u ev=%s\n", e.t_s, unsigned{e.channel}, e.at.line, what.c_str());
}

std::optional<std::string> read_text(const std::filesystem::path& p) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(p, ec)) return std::nullopt;
  if (std::filesystem::file_size(p, ec) > nck::config::kMaxListFileBytes || ec) return std::nullopt;
  std::ifstream in(p, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) return fail(nck::ErrorId::HalUsage, "usage: nck-hal MACHINE_FOLDER PROGRAM");
  const std::filesystem::path folder = argv[1], program = argv[2];
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec))
    return fail(nck::ErrorId::HalUsage, fmt::format("the machine folder '{}' does not exist", folder.string()));
  if (!std::filesystem::is_regular_file(program, ec))
    return fail(nck::ErrorId::HalUsage, fmt::format("the program '{}' does not exist", program.string()));

  // Load as the real-time side will, recording each list it reads: the pack
  // is exactly what loadrt nck needs, and it reads no file itself.
  nck::hal::ListPack pack;
  nck::config::LoadOptions options;
  options.read_text = [&pack](const std::filesystem::path& p) {
    auto text = read_text(p);
    if (text) pack[p.string()] = *text;
    return text;
  };
  auto loaded = nck::config::load_machine(folder, options);
  for (const auto& d : loaded.diagnostics.items())
    if (d.severity == nck::Severity::error)
      std::fprintf(stderr, "%s:%u: error %u: %s\n", d.loc.file.c_str(), d.loc.line, static_cast<unsigned>(d.id),
                   d.message.c_str());
  if (!loaded.ok()) return 1;
  const nck::config::Machine& machine = *loaded.machine;
  pack[""] = folder.string();

  const int comp = hal_init("nck-hal");
  if (comp < 0) return fail(nck::ErrorId::HalSharedMemory, "hal_init failed: is a HAL session running (halrun)?");
  const int shm = rtapi_shmem_new(nck::hal::kLinkKey, comp, sizeof(nck::hal::Link));
  void* mem = nullptr;
  if (shm < 0 || rtapi_shmem_getptr(shm, &mem) != 0 || !mem) {
    hal_exit(comp);
    return fail(nck::ErrorId::HalSharedMemory, "the shared segment cannot be created");
  }
  auto* link = new (mem) nck::hal::Link();
  link->magic = nck::hal::kLinkMagic;
  link->version = nck::hal::kLinkVersion;
  if (!nck::hal::write_pack(*link, pack)) {
    hal_exit(comp);
    return fail(nck::ErrorId::HalSharedMemory, "the machine's lists are larger than the shared pack");
  }
  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);
  hal_ready(comp);

  int rc = 0;
  try {
    nck::prep::PlanStore store;
    nck::prep::ChannelPrep prep(machine, 0, program, store, nck::prep::PrepOptions{});
    std::uint64_t events = 0;
    while (!stop_requested) {
      const bool running = link->rt_state.load() == static_cast<std::uint32_t>(nck::hal::RtState::running);
      const bool done = running && link->cycles.load() > 0 && link->channel_done[0].load() != 0;
      prep.feed(link->commands[0], link->feedback[0], done);
      while (!link->events.empty()) {
        print_event(link->events.front(), machine);
        link->events.pop();
        ++events;
      }
      if (link->rt_state.load() == static_cast<std::uint32_t>(nck::hal::RtState::error)) {
        rc = fail(nck::ErrorId::HalRealtimeGone, fmt::format("nck.cycle stopped with error {}", link->rt_error_id.load()));
        break;
      }
      if (done && link->events.empty()) {
        std::printf("nck-hal: channel 1 done after %llu cycles, %llu events (%u dropped)\n",
                    static_cast<unsigned long long>(link->cycles.load()), static_cast<unsigned long long>(events),
                    link->events_dropped.load());
        break;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
  } catch (const std::exception& e) {
    rc = fail(nck::ErrorId::AppInternalError, e.what());
  }
  std::fflush(stdout);
  // The segment stays mapped in rtapi_app after we leave (halcmd waitusr
  // nck-hal returns here: the HAL file's end).
  hal_exit(comp);
  return rc;
}
