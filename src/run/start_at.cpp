#include "nck/run/start_at.hpp"

#include "nck/run/stop_at.hpp"

#include <string>

namespace nck::app {
namespace {

// <value>[:<pass>][@<program>]
std::optional<prep::SearchMark> with_pass_and_program(prep::SearchMark::Kind kind, std::string_view text) {
  prep::SearchMark m;
  m.kind = kind;
  if (const std::size_t at = text.find('@'); at != std::string_view::npos) {
    m.program = std::string(text.substr(at + 1));
    if (m.program.empty()) return std::nullopt;
    text = text.substr(0, at);
  }
  if (const std::size_t colon = text.find(':'); colon != std::string_view::npos) {
    const auto pass = whole_number(text.substr(colon + 1), 1);
    if (!pass || *pass > UINT32_MAX) return std::nullopt;
    m.pass = static_cast<std::uint32_t>(*pass);
    text = text.substr(0, colon);
  }
  const auto value = whole_number(text, 0);
  if (!value) return std::nullopt;
  m.value = *value;
  return m;
}

}  // namespace

std::optional<prep::SearchMark> parse_start_at(std::string_view text) {
  if (text.size() < 2 || (text[0] != 'N' && text[0] != 'n')) return std::nullopt;
  return with_pass_and_program(prep::SearchMark::Kind::block_number, text.substr(1));
}

std::optional<prep::SearchMark> parse_start_at_offset(std::string_view text) {
  return with_pass_and_program(prep::SearchMark::Kind::file_offset, text);
}

std::optional<prep::SearchMark> parse_start_at_block(std::string_view text) {
  const auto k = whole_number(text, 1);
  if (!k) return std::nullopt;
  prep::SearchMark m;
  m.kind = prep::SearchMark::Kind::block_counter;
  m.value = *k;
  return m;
}

}  // namespace nck::app
