#pragma once
// nck diff's pairing of two runs' blocks (docs/decisions.md, "Run diff"):
// by identity — file, local subroutine, NC text and pass, as --final's
// block rows carry it (nck/output/block_identity.hpp) — and the blocks left
// over by their N number, so that lines inserted into a program shift no
// block onto another. Rows without an identity (a final state of an older
// nck, a file that could not be read) are matched by line as before.
#include <string>

#include <nlohmann/json.hpp>

namespace nck::app {

// Rows {key, n, text, line_a, line_b, a_s, b_s, delta_s} (text_b where a
// pair by N number has another text), the largest change first; null where
// a side has no such block. `main_a` / `main_b`: each channel's main
// program file, whose blocks are named without a file.
nlohmann::ordered_json compare_blocks(const nlohmann::json& rows_a, const std::string& main_a,
                                      const nlohmann::json& rows_b, const std::string& main_b);

}  // namespace nck::app
