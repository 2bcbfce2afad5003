#pragma once
// Where in the program something happened: the file (the decoder's file id),
// its line and the block's N number when it has one. Plain data: it travels
// with commands and events through the real-time queues.
#include <cstdint>
#include <optional>

namespace nck {

struct BlockRef {
  std::uint16_t file_id = 0;
  std::uint32_t line = 0;  // 0: no block (a machine event, or before the first block)
  std::optional<std::int64_t> n;
};

}  // namespace nck
