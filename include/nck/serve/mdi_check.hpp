#pragma once
// An MDI text the API answers 422 for (docs/api.md): decoded before it is
// queued, with a decoder of its own, so that text that does not decode is
// answered with its diagnostic at once instead of failing later on the
// event stream only (issue 47 item 5).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"

namespace nck::app::serve {

// The first error of `text` for channel ch (0-based) when it is one of the
// text's own (a character, word, G code, expression or # command the
// decoder cannot read), else nothing. Errors that depend on the channel's
// state where the MDI text will run (a variable the program set, the
// modal state, a subroutine file) are not decided here: the run reports
// them (last_error, the stream). `roots`: the folders a file may be read from.
std::optional<Diagnostic> mdi_text_error(const config::Machine& m, std::size_t ch, const std::string& text,
                                         const std::vector<std::filesystem::path>& roots);

}  // namespace nck::app::serve
