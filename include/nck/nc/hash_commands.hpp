#pragma once
// Typed # commands (SPEC 3.2, facts sheet A, B, D). The decoder checks their
// syntax and arguments; their execution belongs to the kernel.
// (Skeleton: the decoder work fills in every command's fields.)
#include <string>
#include <variant>

namespace nck::nc {

struct HashUnknownPlaceholder {
  std::string text;
};

using HashCommand = std::variant<HashUnknownPlaceholder>;

// The command's keyword as written in the program, e.g. "#CS ON".
std::string hash_command_name(const HashCommand& c);

}  // namespace nck::nc
