#pragma once
// JSON view of a decoded block (for `nck parse --json`): the file, line and
// N number, axis words by configured name, modal state, spindle commands
// and the # command with its fields. Absent words are left out.
#include <nlohmann/json.hpp>

#include "nck/nc/block.hpp"
#include "nck/nc/decoder.hpp"

namespace nck::nc {

nlohmann::json to_json(const Block& b, const Decoder& d);
nlohmann::json to_json(const ModalState& m);
nlohmann::json to_json(const SpindleCommand& s);
nlohmann::json to_json(const HashCommand& h);

}  // namespace nck::nc
