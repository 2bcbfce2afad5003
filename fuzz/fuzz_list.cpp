// libFuzzer target: any bytes as a parameter list, split into lines and
// typed against the registry as the list kind the first byte picks (typing
// against the wrong kind makes every key unknown, and each unknown key
// costs a did-you-mean search: one kind per input keeps the rate up).
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string_view>

#include "nck/config/list_reader.hpp"
#include "nck/config/param_list.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  nck::Diagnostics diags;
  const nck::config::ListText list = nck::config::read_list_text(text, "fuzz.lis", diags);
  constexpr nck::config::ListKind kinds[] = {nck::config::ListKind::startup, nck::config::ListKind::channel,
                                              nck::config::ListKind::axis,    nck::config::ListKind::tool,
                                              nck::config::ListKind::zero,    nck::config::ListKind::clamp,
                                              nck::config::ListKind::sim};
  const auto kind = kinds[size > 0 ? data[0] % std::size(kinds) : 0];
  (void)nck::config::ParamList::parse(list, kind, diags);
  return 0;
}
