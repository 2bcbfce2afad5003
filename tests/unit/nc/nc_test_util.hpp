#pragma once
// Helpers for the decoder tests: write a program to a temporary folder,
// decode it completely, and look at blocks and diagnostics.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "nck/nc/decoder.hpp"

namespace nck::nc::test {

inline std::filesystem::path temp_dir() {
  static std::atomic<int> counter{0};
  auto d = std::filesystem::temp_directory_path() /
           ("nck_nc_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  std::filesystem::create_directories(d);
  return d;
}

inline std::filesystem::path write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

inline DecoderConfig default_config() {
  DecoderConfig c;
  c.axis_names = {"X", "Y", "Z", "C1", "X2"};
  c.spindle_names = {"S1", "S2", "S3"};
  c.spindle_log_axis_numbers = {6, 11, 30};
  return c;
}

struct Decoded {
  std::vector<Block> blocks;
  std::vector<Diagnostic> diags;
  Decoder::Status last = Decoder::Status::end;
  std::vector<std::string> files;

  bool has(ErrorId id) const {
    for (const auto& d : diags)
      if (d.id == id) return true;
    return false;
  }
  const Diagnostic* find(ErrorId id) const {
    for (const auto& d : diags)
      if (d.id == id) return &d;
    return nullptr;
  }
  std::size_t errors() const {
    std::size_t n = 0;
    for (const auto& d : diags) n += d.severity == Severity::error;
    return n;
  }
};

inline Decoded decode_file(const std::filesystem::path& p, DecoderConfig cfg = default_config(),
                           std::size_t max_blocks = 100000) {
  Decoded r;
  Decoder dec(p, std::move(cfg));
  for (std::size_t i = 0; i < max_blocks; ++i) {
    auto res = dec.next();
    r.last = res.status;
    if (res.status != Decoder::Status::block) {
      if (res.status == Decoder::Status::error && dec.config().continue_after_error) continue;
      break;
    }
    r.blocks.push_back(std::move(res.block));
  }
  r.diags = dec.diagnostics();
  for (std::uint16_t i = 0; i < 8; ++i) r.files.push_back(dec.file_name(i));
  return r;
}

inline Decoded decode(const std::string& text, DecoderConfig cfg = default_config()) {
  auto p = write_file(temp_dir() / "prog.nc", text);
  return decode_file(p, std::move(cfg));
}

inline std::string dump(const Decoded& d) {
  std::string s;
  for (const auto& x : d.diags) s += format(x) + "\n";
  return s;
}

// The X word of every decoded block that has one, in order.
inline std::vector<double> xs(const Decoded& d) {
  std::vector<double> r;
  for (const auto& b : d.blocks)
    if (b.axes[0]) r.push_back(*b.axes[0]);
  return r;
}

// Block i's # command, which must be a T.
template <class T>
const T& cmd(const Decoded& d, std::size_t i) {
  EXPECT_LT(i, d.blocks.size()) << dump(d);
  EXPECT_TRUE(d.blocks.at(i).hash.has_value());
  return std::get<T>(*d.blocks.at(i).hash);
}

}  // namespace nck::nc::test
