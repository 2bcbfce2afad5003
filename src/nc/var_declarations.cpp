// #VAR .. #ENDVAR: one declaration per block,
//   V.L.NAME[dim]..[: TYPE[len]] [= value | = [v, v, ..] | = "text"]
#include <cmath>
#include <fmt/format.h>

#include "decoder_impl.hpp"

namespace nck::nc {

using namespace detail;

namespace {
constexpr std::string_view kTypes[] = {"BOOLEAN", "UNS08", "SGN08", "UNS16", "SGN16", "UNS32",
                                       "SGN32", "UNS64", "SGN64", "REAL32", "REAL64", "REAL",
                                       "INT", "CHAR", "STRING"};
}

Outcome Decoder::Impl::declare(Cursor& c) {
  std::size_t at = c.pos;
  auto bad = [&](std::size_t pos, std::string msg) { return report(ErrorId::NcVarDeclaration, pos, std::move(msg)); };
  if (!(upper(c.peek()) == 'V' && c.peek(1) == '.'))
    return bad(at, "a declaration starts with V.L., V.P., V.S. or V.CYC. (e.g. V.P.COUNT : REAL64 = 0)");
  c.pos += 2;
  std::string base = "V.";
  std::string_view scope = c.read_ident();
  std::string su = to_upper(scope);
  if (su != "L" && su != "P" && su != "S" && su != "CYC")
    return bad(at, fmt::format("V.{}. variables cannot be declared; use V.L., V.P., V.S. or V.CYC.", scope));
  base += su;
  while (c.peek() == '.' && (is_alpha(c.peek(1)) || c.peek(1) == '_')) {
    ++c.pos;
    base += '.';
    base += to_upper(c.read_ident());
  }
  if (base.size() == su.size() + 2) return bad(c.pos, "variable name expected after the scope");
  std::vector<int> dims;
  while (c.peek() == '[') {
    ++c.pos;
    double v = 0;
    if (!eval_expr(c, x, v)) return Outcome::error;
    c.skip_spaces();
    if (!c.match(']') || v < 1 || v != std::round(v) || v > 100000)
      return bad(c.pos, "array size must be an integer >= 1 in [ ]");
    dims.push_back(static_cast<int>(v));
  }
  c.skip_spaces();
  bool is_string = false;
  std::size_t string_chars = 0;
  if (c.match(':')) {
    c.skip_spaces();
    std::size_t tp = c.pos;
    std::string t = to_upper(c.read_ident());
    bool known = false;
    for (auto k : kTypes) known = known || t == k;
    if (!known) return bad(tp, fmt::format("unknown type '{}' (BOOLEAN, UNS/SGN08..64, REAL32/64, STRING[n])", t));
    is_string = t == "STRING";
    c.skip_spaces();
    if (c.match('[')) {
      const std::size_t len_at = c.pos;
      double len = 0;
      if (!eval_expr(c, x, len)) return Outcome::error;
      c.skip_spaces();
      if (!c.match(']')) return bad(c.pos, "']' expected after the string length");
      if (!(len >= 1 && len <= static_cast<double>(kMaxStringChars)) || len != std::round(len))
        return bad(len_at, fmt::format("a string length is a whole number from 1 to {} (a block's length), not {}",
                                       kMaxStringChars, len));
      if (is_string) string_chars = static_cast<std::size_t>(len);
    }
  }
  switch (vars.declare(base, dims, is_string, string_chars)) {
    case Variables::Declared::ok: break;
    case Variables::Declared::array_too_large: return bad(at, "the array is too large (at most 100000 elements)");
    case Variables::Declared::memory_cap:
      return report(ErrorId::NcVariableMemory, at,
                    fmt::format("declaring {} would take the program's variables past {} elements or {} MiB "
                                "(8 bytes per number, the declared length per string)",
                                base, cfg.max_variable_elements, cfg.max_variable_bytes >> 20));
  }
  c.skip_spaces();
  if (!c.match('=')) return c.rest_empty() ? Outcome::nothing : bad(c.pos, "'=' or end of declaration expected");
  c.skip_spaces();
  if (c.peek() == '"') {
    std::size_t e = c.s.find('"', c.pos + 1);
    if (e == std::string_view::npos) return bad(c.pos, "string without closing \"");
    if (!is_string || !dims.empty()) return report(ErrorId::NcTypeMismatch, c.pos, "a string needs a scalar STRING variable");
    vars.write_string(base, std::string(c.s.substr(c.pos + 1, e - c.pos - 1)));
    c.pos = e + 1;
    return c.rest_empty() ? Outcome::nothing : bad(c.pos, "unexpected text after the value");
  }
  if (is_string) return report(ErrorId::NcTypeMismatch, c.pos, "a STRING variable is initialised with \"text\"");
  if (dims.empty()) {
    double v = 0;
    if (!eval_expr(c, x, v)) return Outcome::error;
    vars.write(base, v);
    return c.rest_empty() ? Outcome::nothing : bad(c.pos, "unexpected text after the value");
  }
  // Array: [v, v, ...] in row-major order.
  if (!c.match('[')) return bad(c.pos, "an array is initialised with [v, v, ...]");
  std::size_t total = 1;
  for (int d : dims) total *= static_cast<std::size_t>(d);
  std::vector<int> idx(dims.size(), 0);
  for (std::size_t n = 0;; ++n) {
    c.skip_spaces();
    double v = 0;
    if (!eval_expr(c, x, v)) return Outcome::error;
    if (n >= total) return report(ErrorId::NcIndexOutOfRange, c.pos, "more values than array elements");
    std::string key = base;
    for (int i : idx) key += fmt::format("[{}]", i);
    vars.write(key, v);
    for (std::size_t k = dims.size(); k-- > 0;) {
      if (++idx[k] < dims[k]) break;
      idx[k] = 0;
    }
    c.skip_spaces();
    if (c.match(']')) break;
    if (!c.match(',')) return bad(c.pos, "',' or ']' expected in the value list");
  }
  return c.rest_empty() ? Outcome::nothing : bad(c.pos, "unexpected text after the value list");
}

}  // namespace nck::nc
