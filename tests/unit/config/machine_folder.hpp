#pragma once
// Test helper: a small machine folder in a fresh temporary directory.
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>

#include "nck/config/load.hpp"

namespace nck::config::test {

// One X axis (logical 1) and spindle S1 (logical 2, main) in channel 1.
inline std::map<std::string, std::string> minimal_machine() {
  return {
      {"startup.lis", "sda_mds[0] ch.lis\nachs_mds[0] x.lis\nachs_mds[1] s1.lis\n"},
      {"x.lis", "kopf.achs_nr 1\nkenngr.achs_typ 1\n"},
      {"s1.lis", "kopf.achs_nr 2\nkenngr.achs_typ 4\n"},
      {"ch.lis",
       "gruppe[0].achse[0].bezeichnung X\n"
       "gruppe[0].achse[0].log_achs_nr 1\n"
       "spdl_anzahl 1\n"
       "main_spindle_ax_nr 2\n"
       "spindel[0].bezeichnung S1\n"
       "spindel[0].log_achs_nr 2\n"},
  };
}

class MachineFolder {
 public:
  explicit MachineFolder(const std::map<std::string, std::string>& files = minimal_machine()) {
    static std::atomic<int> counter{0};
    dir_ = std::filesystem::temp_directory_path() /
           ("nck_config_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    for (const auto& [name, text] : files) write(name, text);
  }
  ~MachineFolder() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  MachineFolder(const MachineFolder&) = delete;
  MachineFolder& operator=(const MachineFolder&) = delete;

  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  void append(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary | std::ios::app) << text;
  }
  const std::filesystem::path& dir() const { return dir_; }
  std::string file(const std::string& name) const { return (dir_ / name).lexically_normal().string(); }
  LoadResult load() const { return load_machine(dir_); }

 private:
  std::filesystem::path dir_;
};

// The diagnostics with `id`.
inline std::vector<Diagnostic> with_id(const Diagnostics& d, ErrorId id) {
  std::vector<Diagnostic> out;
  std::copy_if(d.items().begin(), d.items().end(), std::back_inserter(out),
               [id](const Diagnostic& x) { return x.id == id; });
  return out;
}

inline std::string dump(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.items()) s += format(x) + "\n";
  return s;
}

// The first gear stage of the first axis (X of the minimal machine).
inline const GearStage& x_gear(const LoadResult& r) { return r.machine->axes.at(0).gears.at(0); }

}  // namespace nck::config::test
