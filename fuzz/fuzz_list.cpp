// libFuzzer target: any bytes as a parameter list. The first byte picks the
// list kind and the path: bit 7 clear, the text is split and typed against
// the registry as that kind (fast: typing against the wrong kind makes every
// key unknown, and each unknown key costs a did-you-mean search, so one kind
// per input keeps the rate up); bit 7 set, the text replaces that list of a
// copy of the milling example and the whole machine is loaded (file
// reading, building, plausibility checks: the path of `nck check`).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <unistd.h>

#include "nck/config/list_reader.hpp"
#include "nck/config/load.hpp"
#include "nck/config/param_list.hpp"

namespace {

namespace fs = std::filesystem;

// A copy of examples/mill per fuzzing process, removed when it exits.
struct MachineCopy {
  fs::path dir = fs::temp_directory_path() / ("nck_fuzz_machine_" + std::to_string(::getpid()));
  MachineCopy() {
    fs::remove_all(dir);
    fs::copy(NCK_SOURCE_DIR "/examples/mill", dir, fs::copy_options::recursive);
  }
  ~MachineCopy() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

const fs::path& machine_copy() {
  static const MachineCopy copy;
  return copy.dir;
}

void load_whole_machine(std::string_view text, std::uint8_t pick) {
  static constexpr const char* kFiles[] = {"startup.lis", "channel1.lis", "x.lis", "tools.lis",
                                           "zero.lis",    "clamp.lis",    "sim.lis", "s1.lis"};
  const fs::path file = machine_copy() / kFiles[pick % std::size(kFiles)];
  std::string original;
  {
    std::ifstream in(file, std::ios::binary);
    original.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(text.data(), static_cast<std::streamsize>(text.size()));
  (void)nck::config::load_machine(machine_copy());
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(original.data(), static_cast<std::streamsize>(original.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::uint8_t first = size > 0 ? data[0] : 0;
  if (first & 0x80) {
    load_whole_machine(text, first);
    return 0;
  }
  nck::Diagnostics diags;
  const nck::config::ListText list = nck::config::read_list_text(text, "fuzz.lis", diags);
  constexpr nck::config::ListKind kinds[] = {nck::config::ListKind::startup, nck::config::ListKind::channel,
                                              nck::config::ListKind::axis,    nck::config::ListKind::tool,
                                              nck::config::ListKind::zero,    nck::config::ListKind::clamp,
                                              nck::config::ListKind::sim};
  const auto kind = kinds[first % std::size(kinds)];
  (void)nck::config::ParamList::parse(list, kind, diags);
  return 0;
}
