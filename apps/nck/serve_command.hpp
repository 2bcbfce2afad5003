#pragma once
// `nck serve MACHINE [PROGRAM...]`: the kernel live behind the browser HMI
// and the API (docs/api.md).
#include <cstdint>
#include <string>
#include <vector>

namespace nck::app {

struct ServeOptions {
  std::string machine;
  std::vector<std::string> programs;  // loaded at start (channel 1, 2, ...), started by cycle start
  std::string bind = "127.0.0.1";
  std::uint16_t port = 8765;           // 0: a free one
  std::string token_file;              // needed to bind beyond loopback
  std::vector<std::string> folders;    // --programs DIR: what may be loaded
  std::string uploads;                 // folder for uploaded programs (default: a new temporary one)
  std::string speed = "1";             // simulated seconds per wall second, or "max"
  bool strict_keys = false;            // --strict: every unknown list key is an error (910032)
  bool realtime = true;                // ask for SCHED_FIFO and locked memory
  bool paused = false;
  std::size_t max_clients = 8;         // connections with the token
  std::size_t max_anonymous = 4;       // connections without a token yet, per address
  double header_timeout_s = 5;         // a complete request, until one brought the token
  double rate = 50;                    // requests per second per client
  std::size_t max_program_bytes = 4 * 1024 * 1024;
  double max_wall_s = 0;               // stop after this many seconds (tests, benchmarks)
};

// 0 after --max-wall, 2 when it cannot start; after SIGINT/SIGTERM main_cli
// makes it 130/143 (docs/api.md).
int serve_command(const ServeOptions& opt);

}  // namespace nck::app
