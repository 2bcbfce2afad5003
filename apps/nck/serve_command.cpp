// `nck serve`: load the machine, start the live kernel and the server, print
// the URL with its token, serve until SIGINT/SIGTERM (or --max-wall).
#include "serve_command.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "nck/config/load.hpp"
#include "nck/run/stop_request.hpp"
#include "nck/serve/access.hpp"
#include "nck/serve/serve_api.hpp"
#include "nck/serve/speed_range.hpp"
#include "nck/serve/uploads_folder.hpp"

namespace nck::app {
namespace {

namespace fs = std::filesystem;

int bad_options(const std::string& why) {
  fmt::print(stderr, "nck serve: error {}: {}\n", number(ErrorId::ServeBadOptions), why);
  return 2;
}

std::optional<double> speed_of(const std::string& text) {
  if (text == "max") return serve::kSpeedMax;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || v == serve::kSpeedMax || !serve::speed_allowed(v)) return std::nullopt;
  return v;
}

// --uploads, or a new private folder (removed at the end). `guarded`: the
// folders it may neither be nor contain (besides the machine's cycle paths).
std::expected<serve::UploadsFolder, Diagnostic> uploads_folder(const ServeOptions& opt, const config::Machine& m,
                                                               std::vector<fs::path> guarded) {
  if (opt.uploads.empty()) return serve::UploadsFolder::create_private();
  guarded.insert(guarded.end(), m.cycle_paths.begin(), m.cycle_paths.end());
  return serve::UploadsFolder::named(opt.uploads, guarded);
}

}  // namespace

int serve_command(const ServeOptions& opt) {
  const auto speed = speed_of(opt.speed);
  if (!speed)
    return bad_options(fmt::format("--speed '{}' is neither a number in {}..{} nor 'max'", opt.speed, serve::kMinSpeed,
                                   serve::kMaxSpeed));
  std::string why;
  const auto token = serve::read_token(opt.token_file, opt.bind, why);
  if (!token) return bad_options(why);
  config::LoadResult loaded =
      config::load_machine(opt.machine, {opt.strict_keys ? config::KeyPolicy::strict : config::KeyPolicy::lenient});
  for (const Diagnostic& d : loaded.diagnostics.items()) fmt::print(stderr, "{}\n", format(d));
  if (!loaded.ok()) return 2;
  const config::Machine& m = *loaded.machine;

  std::vector<fs::path> roots(opt.folders.begin(), opt.folders.end());
  for (const fs::path& r : roots)
    if (std::error_code ec; !fs::is_directory(r, ec)) return bad_options(fmt::format("--programs {} is no folder", r.string()));
  roots.push_back(opt.machine);
  // A program named on the command line was chosen by whoever started the
  // server: its folder may be read too (its subroutines live there).
  std::vector<std::string> programs;
  for (const std::string& p : opt.programs) {
    const fs::path full = fs::absolute(p);
    roots.push_back(full.parent_path());
    programs.push_back(full.string());
  }
  const auto uploads = uploads_folder(opt, m, roots);
  if (!uploads) {
    fmt::print(stderr, "{}\n", format(uploads.error()));
    return 2;
  }
  serve::ProgramFolders folders(roots, uploads->path(), opt.max_program_bytes);

  auto run = sim::DryRun::create(m, {}, serve::served_run_options(folders));
  if (!run) return bad_options(format(run.error()));
  auto first_run = std::make_unique<sim::DryRun>(std::move(*run));
  first_run->start_preparation_thread();
  serve::LiveKernel kernel(std::move(first_run), *speed);
  kernel.set_paused(opt.paused);
  serve::ServeApi api(m, kernel, std::move(folders));
  for (std::size_t ch = 0; ch < opt.programs.size() && ch < m.channels.size(); ++ch)
    if (auto d = api.load(ch, programs[ch])) {
      fmt::print(stderr, "{}\n", format(*d));
      return 2;
    }

  serve::HttpLimits limits;
  limits.max_clients = opt.max_clients;
  limits.max_anonymous_per_address = opt.max_anonymous;
  limits.header_timeout = std::chrono::milliseconds(static_cast<std::int64_t>(opt.header_timeout_s * 1000));
  limits.requests_per_s = opt.rate;
  limits.max_upload_bytes = opt.max_program_bytes;
  std::optional<serve::HttpServer> server;
  try {
    server.emplace(api, opt.bind, opt.port, *token, limits);
  } catch (const std::exception& e) {
    return bad_options(fmt::format("cannot listen on {}:{}: {}", opt.bind, opt.port, e.what()));
  }
  if (const std::string warning = kernel.start(opt.realtime); !warning.empty()) fmt::print(stderr, "{}\n", warning);
  if (!serve::loopback(opt.bind))
    fmt::print(stderr, "nck serve: warning: plain HTTP on {} carries the token in clear; use it on a trusted network only\n",
               opt.bind);
  const std::string host = opt.bind.find(':') != std::string::npos ? fmt::format("[{}]", opt.bind) : opt.bind;
  fmt::print("nck serve: http://{}:{}/?token={}\n", host, server->port(), *token);
  std::fflush(stdout);
  const WallClockLimit wall(opt.max_wall_s);
  server->run(stop_flag());
  kernel.stop();
  return 0;
}

}  // namespace nck::app
