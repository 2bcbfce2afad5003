#include "nck/serve/mdi_check.hpp"

#include <algorithm>
#include <atomic>

#include "nck/nc/decoder.hpp"
#include "nck/prep/decoder_setup.hpp"

namespace nck::app::serve {
namespace {

// The errors a text has whatever the channel's state: its characters,
// words, G codes, expressions' syntax and # commands.
constexpr ErrorId kTextErrors[] = {
    ErrorId::NcBlockTooLong,      ErrorId::NcUnexpectedCharacter, ErrorId::NcUnknownWord,
    ErrorId::NcUnknownGCode,      ErrorId::NcBadMFunction,        ErrorId::NcModalConflict,
    ErrorId::NcDuplicateWord,     ErrorId::NcAxisTwice,           ErrorId::NcBadValue,
    ErrorId::NcNegativeFeed,      ErrorId::NcBadToolNumber,       ErrorId::NcExprSyntax,
    ErrorId::NcExprTooDeep,       ErrorId::NcUnknownFunction,     ErrorId::NcUnknownControl,
    ErrorId::NcCallSyntax,        ErrorId::NcUnknownHashCommand,  ErrorId::NcHashArguments,
    ErrorId::NcHashNotAlone,      ErrorId::NcGotoSyntax,          ErrorId::NcCycleSyntax,
    ErrorId::NcCycleWord,         ErrorId::NcBadSkipLevel,        ErrorId::NcSpindleKeyword,
    ErrorId::NcUnknownSpindle,    ErrorId::NcSlopeSyntax,         ErrorId::NcUnsupported,
    ErrorId::NcRadiusWithCenter,  ErrorId::NcDwellNotAlone,       ErrorId::NcVariableWithoutAssignment,
};

// A text's check reads a few blocks, not a program: an MDI text that loops
// or calls a long subroutine is left to the run after these.
constexpr int kMaxBlocks = 1000;

}  // namespace

std::optional<Diagnostic> mdi_text_error(const config::Machine& m, std::size_t ch, const std::string& text,
                                         const std::vector<std::filesystem::path>& roots) {
  if (ch >= m.channels.size()) return std::nullopt;
  nc::DecoderConfig cfg = prep::decoder_config(m, ch);
  cfg.allowed_roots = roots;
  cfg.max_loop_iterations = 10'000;
  cfg.max_lines_read = 10'000;
  nc::Decoder dec(cfg);
  dec.run_mdi(text);
  for (int i = 0; i < kMaxBlocks; ++i) {
    const nc::Decoder::Result r = dec.next();
    if (r.status == nc::Decoder::Status::block) continue;
    if (r.status != nc::Decoder::Status::error) return std::nullopt;
    for (const Diagnostic& d : dec.diagnostics()) {
      if (d.severity != Severity::error) continue;
      if (std::find(std::begin(kTextErrors), std::end(kTextErrors), d.id) != std::end(kTextErrors)) return d;
      return std::nullopt;  // the first error is one the channel's state may decide
    }
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace nck::app::serve
