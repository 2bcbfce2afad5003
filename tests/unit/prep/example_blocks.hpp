#pragma once
// Kernel tests on the example machines: a machine loaded once from
// examples/<name>, and blocks made by decoding a program text with that
// machine's own decoder configuration (never hand-built nc::Blocks, whose
// G-code fields change with the decoder).
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "../nc/nc_test_util.hpp"
#include "nck/config/load.hpp"
#include "nck/prep/decoder_setup.hpp"

namespace nck::prep::testing {

// examples/<name>, loaded and checked once per test program.
inline const config::Machine& example_machine(const std::string& name) {
  static std::map<std::string, config::Machine> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  config::LoadResult r = config::load_machine(std::filesystem::path(NCK_SOURCE_DIR) / "examples" / name);
  EXPECT_TRUE(r.ok()) << name;
  return cache.emplace(name, r.machine.value_or(config::Machine{})).first->second;
}

// The blocks of `text` as channel `ch` of `m` decodes them; a decoder error
// fails the test (the text is meant to be valid).
inline std::vector<nc::Block> decode_blocks(const config::Machine& m, const std::string& text,
                                            std::size_t ch = 0) {
  nc::test::Decoded d = nc::test::decode(text, prep::decoder_config(m, ch));
  EXPECT_EQ(d.errors(), 0u) << nc::test::dump(d);
  return d.blocks;
}

}  // namespace nck::prep::testing
