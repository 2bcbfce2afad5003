// libFuzzer target: any bytes as an NC program through the decoder in lint
// mode (every block, past errors) with a small loop budget, so that each
// input ends quickly. The decoder reads files: the input goes to one
// temporary file per fuzzing process.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "nck/nc/decoder.hpp"

namespace {

const std::filesystem::path& program_path() {
  static const std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("nck_fuzz_" + std::to_string(::getpid()) + ".nc");
  return p;
}

nck::nc::DecoderConfig config() {
  nck::nc::DecoderConfig c;
  c.axis_names = {"X", "Y", "Z", "A", "B", "C"};
  c.spindle_names = {"S1", "S2"};
  c.spindle_log_axis_numbers = {6, 7};
  c.main_spindle = "S1";
  c.continue_after_error = true;
  c.max_loop_iterations = 20'000;
  c.max_lines_read = 500'000;  // the reading budget: a few seconds under ASan+UBSan
  c.max_variable_elements = 50'000;
  return c;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream f(program_path(), std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  nck::nc::Decoder d(program_path(), config());
  for (int blocks = 0; blocks < 100'000; ++blocks) {
    const std::size_t before = d.diagnostics().size();
    const nck::nc::Decoder::Result r = d.next();
    if (r.status == nck::nc::Decoder::Status::end || r.status == nck::nc::Decoder::Status::stopped) break;
    if (r.status == nck::nc::Decoder::Status::error && d.diagnostics().size() == before) break;
  }
  return 0;
}
