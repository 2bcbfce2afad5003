#pragma once
// The one JSON shape of a diagnostic (one occurrence of an error or warning)
// on every surface: `nck check --json`, the events' error and warning
// lines, --final's errors, the API's refusals and state, the Python module
// (issue 47 item 5; docs/outputs.md, "The diagnostic"):
//   {id, severity, name, message, remedy, file, line, column, channel}
// A field that does not apply is left out, never a placeholder: no file
// (""), no line (0), no column (0), no channel (0, the machine's).
// The catalogue of IDs (`nck errors`, GET /api/v1/errors, nck.errors()) is
// another concept with a shape of its own: {id, severity, name, cause, remedy}.
#include <cstddef>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "nck/core/diagnostic.hpp"

namespace nck::app {

// `channel`: 1-based, 0 when the diagnostic belongs to no channel.
// `severity`: the occurrence's when it has one, else the table's.
nlohmann::ordered_json diagnostic_json(ErrorId id, std::string_view message, const SourceLoc& loc,
                                       std::size_t channel = 0, std::optional<Severity> severity = std::nullopt);
nlohmann::ordered_json diagnostic_json(const Diagnostic& d, std::size_t channel = 0);

// Adds the diagnostic's fields that `into` lacks, after its own: the events
// and --final keep their first fields (id, ch, line, file, msg) and gain
// the rest (extend, never rename).
void add_diagnostic_fields(nlohmann::ordered_json& into, const nlohmann::ordered_json& diagnostic);

// One entry of the catalogue: {id, severity, name, cause, remedy}.
nlohmann::ordered_json catalogue_json(const ErrorInfo& e);
// Every entry, in table order.
nlohmann::ordered_json catalogue_json();

}  // namespace nck::app
