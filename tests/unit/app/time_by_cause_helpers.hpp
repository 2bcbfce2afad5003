#pragma once
// Time by cause tests (issue 31): run a constructed program, read --final's
// time_by_cause, and find a block's largest class.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {

using nlohmann::json;

struct CauseRun {
  int exit_code = -1;
  json final;
  std::string output;
};

inline CauseRun run_program(const std::string& name, const std::string& program, const std::string& plc = {},
                const std::string& machine = mill()) {
  const auto dir = temp_dir("cause_" + name);
  const auto prog = write(dir / "prog.nc", program);
  std::string args = "run " + machine + " " + prog.string() + " --final " + (dir / "final.json").string();
  if (!plc.empty()) args += " --plc " + write(dir / "s.plc", plc).string();
  const CliResult r = run_nck(args);
  CauseRun out{r.exit_code, json::object(), r.output};
  std::ifstream f(dir / "final.json");
  if (f) out.final = json::parse(f, nullptr, false);
  return out;
}

// The block of line `line` (main program) in channel 1's table.
inline json block_of(const json& final, std::uint32_t line) {
  for (const json& b : final["time_by_cause"]["channels"][0]["blocks"])
    if (b["line"] == line) return b;
  return json::object();
}

// The block's largest class and its share of the block's time.
inline std::pair<std::string, double> dominant(const json& block) {
  if (!block.contains("causes") || block["causes"].empty()) return {"(none)", 0};
  const json& c = block["causes"][0];
  return {c["name"].get<std::string>(), c["share"].get<double>()};
}

inline void expect_dominant(const CauseRun& r, std::uint32_t line, const std::string& name) {
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto [got, share] = dominant(block_of(r.final, line));
  EXPECT_EQ(got, name) << "line " << line << "\n" << block_of(r.final, line).dump(1);
  EXPECT_GE(share, 0.9) << "line " << line << "\n" << block_of(r.final, line).dump(1);
}

}  // namespace nck::app::testing
