// nck-hal: the userspace half of nck in HAL
//   loadusr -W nck-hal [--serve [--port N] [--bind ADDR] [--token-file F]] MACHINE PROGRAM
// Runs as the invoking user: reads the machine folder and the program, packs
// the machine's lists into the shared segment for loadrt nck, then decodes
// and prepares the program into the shared command queues while nck.cycle
// runs it, and prints the kernel's events. Ends when the channel is done,
// the real-time side reports an error, or on SIGTERM (halcmd unloadusr).
// With --serve it also serves nck serve's API and HMI for the kernel in the
// HAL thread (hal_api.hpp) and keeps serving after the end until SIGTERM.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <thread>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "hal.h"
#include "rtapi.h"

#include "hal/hal_api.hpp"
#include "hal/hal_records.hpp"
#include "hal/link.hpp"
#include "nck/config/list_reader.hpp"
#include "nck/config/load.hpp"
#include "nck/prep/channel_prep.hpp"
#include "nck/prep/plan_store.hpp"
#include "nck/serve/access.hpp"

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
  if (const auto* w = e.get<nck::kernel::ev::WaitEnd>())
    what = fmt::format("wait_end reason={}", nck::kernel::wait_reason_name(w->reason));
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

// Prepares the program into the Link while nck.cycle runs it, prints its
// events (and hands them and its state to the API), until the channel is
// done or nck.cycle stopped; with the API, on until SIGTERM.
int feed_and_watch(nck::hal::Link& link, nck::prep::ChannelPrep& prep, const nck::config::Machine& machine,
                   nck::hal::HalApi* api) {
  int rc = 0;
  bool finished = false;
  std::uint64_t events = 0;
  while (!stop_requested) {
    const bool running = link.rt_state.load() == static_cast<std::uint32_t>(nck::hal::RtState::running);
    const bool done = running && link.cycles.load() > 0 && link.channel_done[0].load() != 0;
    // Decoding starts with nck.cycle's first cycle: the skip levels the HAL
    // file set before `start` then rule the program's first blocks too.
    if (!finished && running) {
      prep.set_skip_mask(link.skip_mask[0].load(std::memory_order_relaxed));  // blocks decoded from now on
      prep.feed(link.commands[0], link.feedback[0], done);
    }
    for (; !link.events.empty(); link.events.pop(), ++events) {
      print_event(link.events.front(), machine);
      if (api) api->take_event(link.events.front());
    }
    if (api) api->take_state();
    if (!finished && link.rt_state.load() == static_cast<std::uint32_t>(nck::hal::RtState::error)) {
      rc = fail(nck::ErrorId::HalRealtimeGone, fmt::format("nck.cycle stopped with error {}", link.rt_error_id.load()));
      finished = true;
    } else if (!finished && done && link.events.empty()) {
      std::printf("nck-hal: channel 1 done after %llu cycles, %llu events (%u dropped)\n",
                  static_cast<unsigned long long>(link.cycles.load()), static_cast<unsigned long long>(events),
                  link.events_dropped.load());
      std::fflush(stdout);
      finished = true;
    }
    if (finished && !api) break;
    std::this_thread::sleep_for(std::chrono::microseconds(finished ? 5000 : 500));
  }
  return rc;
}

struct Options {
  std::filesystem::path folder, program;
  bool serve = false;
  std::string bind = "127.0.0.1";
  std::uint16_t port = 8765;  // 0: a free one
  std::string token_file;
};

// The server for --serve, bound before HAL is told nck-hal is ready (a port
// in use fails the HAL file's loadusr -W), with the URL printed.
std::unique_ptr<nck::app::serve::HttpServer> start_server(const Options& opt, nck::hal::HalApi& api, int& rc) {
  std::string why;
  const auto token = nck::app::serve::read_token(opt.token_file, opt.bind, why);
  if (!token) {
    rc = fail(nck::ErrorId::HalServeOptions, why);
    return nullptr;
  }
  std::unique_ptr<nck::app::serve::HttpServer> server;
  try {
    server = std::make_unique<nck::app::serve::HttpServer>(api, opt.bind, opt.port, *token, nck::app::serve::HttpLimits{});
  } catch (const std::exception& e) {
    rc = fail(nck::ErrorId::HalServeOptions, fmt::format("cannot listen on {}:{}: {}", opt.bind, opt.port, e.what()));
    return nullptr;
  }
  const std::string host = opt.bind.find(':') != std::string::npos ? fmt::format("[{}]", opt.bind) : opt.bind;
  std::printf("nck-hal: http://%s:%u/?token=%s\n", host.c_str(), unsigned{server->port()}, token->c_str());
  std::fflush(stdout);
  return server;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  CLI::App cli{"nck-hal: the userspace half of nck in a LinuxCNC HAL session (docs/hal.md)", "nck-hal"};
  cli.add_option("MACHINE_FOLDER", opt.folder)->required();
  cli.add_option("PROGRAM", opt.program)->required();
  cli.add_flag("--serve", opt.serve, "serve nck serve's API and HMI for the kernel in the HAL thread");
  cli.add_option("--bind", opt.bind, "the server's address (loopback by default)");
  cli.add_option("--port", opt.port, "the server's port (0: a free one)");
  cli.add_option("--token-file", opt.token_file, "the API token (needed beyond loopback)");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return cli.exit(e);
    return fail(nck::ErrorId::HalUsage, fmt::format("{}; usage: nck-hal [--serve [--port N] [--bind ADDR] "
                                                    "[--token-file FILE]] MACHINE_FOLDER PROGRAM", e.what()));
  }
  const std::filesystem::path folder = opt.folder, program = opt.program;
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
  link->serving.store(opt.serve ? 1 : 0);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);

  int rc = 0;
  try {
    nck::prep::PlanStore store;
    nck::prep::ChannelPrep prep(machine, 0, program, store, nck::prep::PrepOptions{});
    const nck::hal::HalRecords records(machine, store, prep);
    std::unique_ptr<nck::hal::HalApi> api;
    std::unique_ptr<nck::app::serve::HttpServer> server;
    std::jthread serving;
    if (opt.serve) {
      api = std::make_unique<nck::hal::HalApi>(machine, *link, records, program);
      server = start_server(opt, *api, rc);
      if (!server) {
        hal_exit(comp);
        return rc;
      }
      serving = std::jthread([&server] { server->run(stop_requested); });
    }
    // Leaving this block (also by an exception) stops the server before its thread is joined.
    const struct StopServer {
      ~StopServer() { stop_requested = true; }
    } stop_server;
    hal_ready(comp);
    rc = feed_and_watch(*link, prep, machine, api.get());
  } catch (const std::exception& e) {
    stop_requested = true;
    rc = fail(nck::ErrorId::AppInternalError, e.what());
  }
  std::fflush(stdout);
  // The segment stays mapped in rtapi_app after we leave (halcmd waitusr
  // nck-hal returns here: the HAL file's end).
  hal_exit(comp);
  return rc;
}
