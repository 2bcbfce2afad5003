#include "nck/output/diagnostic_json.hpp"

#include "nck/core/utf8.hpp"

namespace nck::app {

using json = nlohmann::ordered_json;

namespace {
const char* severity_name(Severity s) { return s == Severity::error ? "error" : "warning"; }
}  // namespace

json diagnostic_json(ErrorId id, std::string_view message, const SourceLoc& loc, std::size_t channel,
                     std::optional<Severity> severity) {
  const ErrorInfo* info = find_error(id);
  json j;
  j["id"] = number(id);
  j["severity"] = severity_name(severity.value_or(info ? info->severity : Severity::error));
  // An ID outside the table (never made by nck itself) still says what it can.
  if (info) j["name"] = std::string(info->name);
  j["message"] = to_utf8(message);
  if (info) j["remedy"] = std::string(info->remedy);
  if (!loc.file.empty()) j["file"] = to_utf8(loc.file);
  if (loc.line > 0) j["line"] = loc.line;
  if (loc.column > 0) j["column"] = loc.column;
  if (channel > 0) j["channel"] = channel;
  return j;
}

json diagnostic_json(const Diagnostic& d, std::size_t channel) {
  return diagnostic_json(d.id, d.message, d.loc, channel, d.severity);
}

void add_diagnostic_fields(json& into, const json& diagnostic) {
  for (auto it = diagnostic.begin(); it != diagnostic.end(); ++it)
    if (!into.contains(it.key())) into[it.key()] = it.value();
}

json catalogue_json(const ErrorInfo& e) {
  return {{"id", number(e.id)},
          {"severity", severity_name(e.severity)},
          {"name", std::string(e.name)},
          {"cause", std::string(e.text)},
          {"remedy", std::string(e.remedy)}};
}

json catalogue_json() {
  json all = json::array();
  for (const ErrorInfo& e : all_errors()) all.push_back(catalogue_json(e));
  return all;
}

}  // namespace nck::app
