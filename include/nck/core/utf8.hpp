#pragma once
// Text from NC programs and list files is bytes: usually ASCII or UTF-8, but
// programs from older German controls carry Latin-1 comments (one byte for
// 'ä'). Everything nck writes as JSON, HTML or CSV is UTF-8.
#include <string>
#include <string_view>

namespace nck {

// Valid UTF-8 sequences are kept; every other byte is taken as Latin-1
// (ISO 8859-1) and converted, so the result is always valid UTF-8 and a
// Latin-1 'ä' reads as 'ä'.
std::string to_utf8(std::string_view bytes);

}  // namespace nck
