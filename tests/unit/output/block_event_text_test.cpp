// Text written as JSON directly (block events, quoted strings) is byte for
// byte what the JSON library writes.
#include <gtest/gtest.h>

#include <cmath>

#include "nck/core/utf8.hpp"
#include "nck/output/output_writers.hpp"

namespace nck::app {
namespace {

kernel::Event block_event(double t_s, std::uint8_t channel, std::uint32_t line, bool has_n, std::int64_t n) {
  kernel::Event e{{t_s, channel, {}}, kernel::ev::Block{}};
  e.at.line = line;
  if (has_n) e.at.n = n;
  return e;
}

TEST(BlockEventText, SameBytesAsTheJsonObject) {
  const RunNames names;  // no run: the file name is empty
  BlockEventText text;
  std::uint64_t seed = 7;
  const auto next = [&] { return (seed = seed * 6364136223846793005ull + 1442695040888963407ull) >> 33; };
  const double fixed[] = {0.0, 0.001, 0.1, 1.0, 12.345, 5940.731, 1e-7, 123456789.0, 1e21, -0.0};
  for (double t : fixed)
    EXPECT_EQ(text.line(block_event(t, 1, 7, true, 10), names),
              EventWriter::line(block_event(t, 1, 7, true, 10), names));
  for (int i = 0; i < 5000; ++i) {
    const double t = static_cast<double>(next() % 100000000) * 0.001 + (i % 3 == 0 ? 1e-9 * (i % 7) : 0.0);
    const auto e = block_event(t, static_cast<std::uint8_t>(next() % 3), static_cast<std::uint32_t>(next()),
                               next() % 2 == 0, static_cast<std::int64_t>(next()) - (1ll << 30));
    ASSERT_EQ(text.line(e, names), EventWriter::line(e, names)) << t;
  }
  EXPECT_EQ(text.line(block_event(NAN, 1, 1, false, 0), names), EventWriter::line(block_event(NAN, 1, 1, false, 0), names));
}

TEST(JsonQuoted, SameBytesAsDumpJson) {
  std::string all;
  for (int c = 0; c < 256; ++c) all += static_cast<char>(c);  // Latin-1 above 0x7F: to_utf8 converts it
  const std::string texts[] = {"", "G1 X10 Y-5.5 F1000", "(\"quoted\" \\ back)", "tab\there\r\n", all,
                               "\xc3\xa4\xc3\xb6\xc3\xbc UTF-8", std::string("nul\0in", 6)};
  for (const std::string& t : texts) EXPECT_EQ(json_quoted(t), dump_json(nlohmann::ordered_json(to_utf8(t)))) << t;
}

}  // namespace
}  // namespace nck::app
