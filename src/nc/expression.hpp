#pragma once
// Evaluation of ISG arithmetic: [ ] expressions, P parameters, variables and
// functions (trig in degrees). Evaluated directly while parsing: no syntax
// tree is built, so a plain number costs no allocation.
#include <cstdint>
#include <string>

#include "lexer.hpp"
#include "variables.hpp"

namespace nck::nc::detail {

struct ExprCtx {
  Variables& vars;
  ErrorSlot& err;
  int depth = 0;
};

// A full expression: logic, comparison and arithmetic operators. Stops
// before ',', ']' or anything that cannot continue the expression.
bool eval_expr(Cursor& c, ExprCtx& x, double& out);
// A word value: [-] number | [expr] | P.. | V.. | FUNC[..] (no binary operators).
bool eval_value(Cursor& c, ExprCtx& x, double& out);

// Something that can be assigned: P<n>, P[expr] or a V. variable.
struct Lvalue {
  bool is_p = false;
  bool is_cycle_p = false;  // @P<n>: a cycle's transfer parameter (p holds n)
  std::int64_t p = 0;
  std::string key;     // normalised V. name
  std::size_t pos = 0; // where it was written
};
// At 'P', '@P' or 'V.': parses the target name (indices evaluated). false + error otherwise.
bool parse_lvalue(Cursor& c, ExprCtx& x, Lvalue& lv);
bool looks_like_lvalue(const Cursor& c);
bool read_lvalue(const Lvalue& lv, ExprCtx& x, double& out);
bool write_lvalue(const Lvalue& lv, ExprCtx& x, double v);

}  // namespace nck::nc::detail
