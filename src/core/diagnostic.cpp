#include "nck/core/diagnostic.hpp"

#include <algorithm>
#include <iterator>
#include <fmt/format.h>

#include "nck/core/utf8.hpp"

namespace nck {
namespace {

constexpr Severity warning = Severity::warning;
constexpr Severity error = Severity::error;

// A plain array: std::array's deduction guide is a fold over every entry,
// and clang stops folds at 256 arguments.
constexpr ErrorInfo kErrors[] = {
#define NCK_ERROR(name, number, severity, text, remedy) \
  ErrorInfo{ErrorId::name, severity, #name, text, remedy},
#include "nck/core/errors_config.def"
#include "nck/core/errors_nc.def"
#include "nck/core/errors_kernel.def"
#include "nck/core/errors_spindle.def"
#include "nck/core/errors_plc.def"
#include "nck/core/errors_frames.def"
#include "nck/core/errors_app.def"
#undef NCK_ERROR
};

}  // namespace

std::span<const ErrorInfo> all_errors() { return kErrors; }

const ErrorInfo* find_error(ErrorId id) {
  auto it = std::find_if(std::begin(kErrors), std::end(kErrors), [id](const ErrorInfo& e) { return e.id == id; });
  return it == std::end(kErrors) ? nullptr : &*it;
}

Diagnostic make_diagnostic(ErrorId id, SourceLoc loc, std::string message) {
  const ErrorInfo* info = find_error(id);
  Severity sev = info ? info->severity : Severity::error;
  return Diagnostic{id, sev, std::move(loc), std::move(message)};
}

std::string format(const Diagnostic& d) {
  std::string where = d.loc.file.empty() ? std::string("<input>") : d.loc.file;
  if (d.loc.line > 0) where += fmt::format(":{}", d.loc.line);
  if (d.loc.line > 0 && d.loc.column > 0) where += fmt::format(":{}", d.loc.column);
  // The same conversion as every JSON, CSV and HTML output: a Latin-1 list
  // key or file name reaches a UTF-8 terminal or log as text, not raw bytes.
  return to_utf8(fmt::format("{}: {} {}: {}", where, d.severity == Severity::error ? "error" : "warning",
                             number(d.id), d.message));
}

bool Diagnostics::has_errors() const { return error_count() > 0; }

std::size_t Diagnostics::error_count() const {
  return static_cast<std::size_t>(std::count_if(
      items_.begin(), items_.end(),
      [](const Diagnostic& d) { return d.severity == Severity::error; }));
}

}  // namespace nck
