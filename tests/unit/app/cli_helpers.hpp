#pragma once
// Running the nck binary from tests and reading what it wrote.
#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdlib>
#include <map>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include <nlohmann/json.hpp>

namespace nck::app::testing {

inline std::string root() { return NCK_SOURCE_DIR; }

struct CliResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// A shell command line; its stdout (redirect stderr yourself).
inline CliResult run_shell(const std::string& cmd) {
  CliResult r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) r.output.append(buf, n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// args may carry shell redirections of their own.
// Starts the shell command `cmd` (stderr dropped), sends it `sig` after
// `after_ms` and returns the status waitpid reports (-1: it did not start).
inline int run_and_signal(const std::string& cmd, int sig, int after_ms = 700) {
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + cmd + " 2>/dev/null").c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(after_ms));
  kill(pid, sig);
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

inline CliResult run_nck_raw(const std::string& args) { return run_shell(std::string(NCK_BINARY) + " " + args); }

// stdout and stderr together.
inline CliResult run_nck(const std::string& args) { return run_nck_raw(args + " 2>&1"); }

inline std::filesystem::path temp_dir(const std::string& name) {
  auto d = std::filesystem::temp_directory_path() / ("nck_test_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// The mill example machine folder (examples/mill).
inline std::string mill() { return root() + "/examples/mill"; }

// Writes `text` to p as is (binary) and returns p.
inline std::filesystem::path write(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// How often `needle` occurs in `haystack` (overlapping occurrences count).
inline std::size_t count(const std::string& haystack, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = haystack.find(needle); at != std::string::npos; at = haystack.find(needle, at + 1)) ++n;
  return n;
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Every line must be one JSON object.
inline std::vector<nlohmann::json> read_jsonl(const std::filesystem::path& p) {
  std::vector<nlohmann::json> out;
  std::ifstream f(p);
  for (std::string line; std::getline(f, line);) out.push_back(nlohmann::json::parse(line));
  return out;
}

inline std::size_t count_lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

inline std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, sep);) out.push_back(item);
  return out;
}

}  // namespace nck::app::testing

namespace nck::app::testing {

// From a run's trace (t.csv, every cycle) and events (e.jsonl) in dir: the
// first three axis set points when each numbered block starts, i.e. where
// everything before it ended.
inline std::map<long, std::array<double, 3>> positions_at_blocks(const std::filesystem::path& dir) {
  std::map<long, std::array<double, 3>> by_ms;
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto c = split(lines[i], ',');
    by_ms[std::lround(std::stod(c[0]) * 1000)] = {std::stod(c[1]), std::stod(c[2]), std::stod(c[3])};
  }
  std::map<long, std::array<double, 3>> out;
  for (const nlohmann::json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "block" && !e["n"].is_null()) {
      const long ms = std::lround(e["t"].get<double>() * 1000);
      out[e["n"].get<long>()] = ms == 0 ? std::array<double, 3>{} : by_ms.at(ms - 1);
    }
  return out;
}

// A copy of an example machine (in dir/name) with `lines` added before the
// final "Ende" of one list; returns the folder and the first added line's number.
struct PatchedMachine {
  std::filesystem::path dir;
  std::size_t line = 0;
};
inline PatchedMachine patched_example(const std::string& example, const std::string& name,
                                      const std::string& file, const std::string& lines) {
  const auto dir = temp_dir(name) / example;
  std::filesystem::copy(root() + "/examples/" + example, dir, std::filesystem::copy_options::recursive);
  std::string text = read_file(dir / file);
  std::size_t at = text.rfind("Ende");
  if (at == std::string::npos) at = text.size();
  const auto line = static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n')) + 1;
  text.insert(at, lines + "\n");
  std::ofstream(dir / file) << text;
  return {dir, line};
}

// Runs an example program with events and an every-cycle trace into dir.
inline CliResult run_example(const std::string& machine, const std::string& program,
                             const std::filesystem::path& dir, const std::string& args = "") {
  const std::string ex = root() + "/examples/" + machine;
  return run_nck("run " + ex + " " + ex + "/" + program + " --events " + (dir / "e.jsonl").string() +
                 " --trace " + (dir / "t.csv").string() + " " + args);
}

}  // namespace nck::app::testing
