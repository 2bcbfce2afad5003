#pragma once
// Errors are data: every diagnostic the project emits carries an ErrorId from
// one table (the *.def files beside this header), a severity and a location.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace nck {

enum class Severity : std::uint8_t { warning, error };

// The IDs come from X-macro tables, one per layer, so that each layer owns
// its own band without editing a shared enum:
//   NCK_ERROR(Name, number, severity, "what is wrong", "what to change")
// Seed / TF5200 diagnosis numbers are used where the seeds give one; our own
// IDs live in documented bands (docs/errors.md):
//   910000-919999 configuration, 920000-929999 decoder, 950000-959999 spindle,
//   960000-969999 PLC simulation, 970000-979999 frames (coordinate systems),
//   930000-939999 kernel/channel, 940000-949999 command line and files.
enum class ErrorId : std::uint32_t {
#define NCK_ERROR(name, number, severity, text, remedy) name = number,
#include "nck/core/errors_config.def"
#include "nck/core/errors_nc.def"
#include "nck/core/errors_kernel.def"
#include "nck/core/errors_spindle.def"
#include "nck/core/errors_plc.def"
#include "nck/core/errors_frames.def"
#include "nck/core/errors_app.def"
#undef NCK_ERROR
};

struct ErrorInfo {
  ErrorId id;
  Severity severity;
  std::string_view name;
  std::string_view text;    // short description of the cause
  std::string_view remedy;  // what to change
};

// Every known ID, in table order.
std::span<const ErrorInfo> all_errors();
// nullptr for an unknown number.
const ErrorInfo* find_error(ErrorId id);
constexpr std::uint32_t number(ErrorId id) { return static_cast<std::uint32_t>(id); }
// docs/errors.md: every ID as a Markdown table (`nck errors`, the Python
// module's errors_markdown).
std::string errors_markdown();

struct SourceLoc {
  std::string file;
  std::uint32_t line = 0;    // 1-based, 0 = unknown
  std::uint32_t column = 0;  // 1-based, 0 = not applicable
};

struct Diagnostic {
  ErrorId id{};
  Severity severity = Severity::error;
  SourceLoc loc;
  std::string message;  // specific text: what is wrong here and what to change
};

// Builds a diagnostic whose severity comes from the table.
Diagnostic make_diagnostic(ErrorId id, SourceLoc loc, std::string message);

// "FILE:LINE[:COL]: error|warning ID: message"
std::string format(const Diagnostic& d);

// A growing list of diagnostics, used at setup time (never in the cyclic path).
class Diagnostics {
 public:
  void add(Diagnostic d) { items_.push_back(std::move(d)); }
  void add(ErrorId id, SourceLoc loc, std::string message) {
    items_.push_back(make_diagnostic(id, std::move(loc), std::move(message)));
  }
  void append(const Diagnostics& other) {
    items_.insert(items_.end(), other.items_.begin(), other.items_.end());
  }
  bool has_errors() const;
  std::size_t error_count() const;
  const std::vector<Diagnostic>& items() const { return items_; }
  bool empty() const { return items_.empty(); }

 private:
  std::vector<Diagnostic> items_;
};

}  // namespace nck
