#pragma once
// What nck refuses by name instead of calling it unknown: the ISG functions
// it does not have (920052) and the ISO/Fanuc words that mean something
// else in ISG, or nothing (the remedy says what to write). One list each,
// so that docs/nc-language.md can be checked against them
// (refused_isg_functions() in decoder.hpp).
#include <optional>
#include <string>
#include <string_view>

#include "lexer.hpp"

namespace nck::nc::detail {

// G<code> is an ISG G function nck does not have.
bool isg_g_function(int code);
// An ISG function of expressions nck does not have (IS_STRING: nck's @P
// hold numbers only); `name_upper` as read.
bool isg_expression_function(std::string_view name_upper);
// `c` after a '#': "#RT CYCLE", "#TOOL ORI", "#MC_MOVEPATH" ... when an ISG
// # function nck does not have follows, else "".
std::string unsupported_hash(Cursor c);
// What to write in ISG for an ISO/Fanuc G<code> that means something else
// there or nothing (G20, G21, G28, G43): a sentence for the message.
std::optional<std::string_view> iso_g_remedy(int code);
// The message for an ISO/Fanuc program number O<digits> at the cursor.
std::string iso_program_number(Cursor c);

}  // namespace nck::nc::detail
