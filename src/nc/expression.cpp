#include "expression.hpp"

#include <cmath>
#include <fmt/format.h>

#include "isg_refusals.hpp"

namespace nck::nc::detail {

namespace {

constexpr int kMaxDepth = 64;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

bool eval_or(Cursor& c, ExprCtx& x, double& out);

bool fail(ExprCtx& x, ErrorId id, std::size_t pos, std::string msg) {
  return x.err.fail(id, pos, std::move(msg));
}

bool status_error(ExprCtx& x, VarStatus s, std::size_t pos, const std::string& name) {
  switch (s) {
    case VarStatus::ok: return true;
    case VarStatus::undefined:
      return fail(x, ErrorId::NcUndefinedVariable, pos,
                  fmt::format("{} has no value yet; assign or declare it before reading it", name));
    case VarStatus::unknown_kernel:
      return fail(x, ErrorId::NcUnknownKernelVariable, pos,
                  fmt::format("{} is not a kernel variable nck knows (axis name or index wrong?)", name));
    case VarStatus::is_string:
      return fail(x, ErrorId::NcTypeMismatch, pos,
                  fmt::format("{} holds a string; a number is needed here", name));
    case VarStatus::not_string:
      return fail(x, ErrorId::NcTypeMismatch, pos,
                  fmt::format("{} is numeric; a string cannot be assigned", name));
    case VarStatus::index_out_of_range:
      return fail(x, ErrorId::NcIndexOutOfRange, pos,
                  fmt::format("index of {} is outside the declared size", name));
    case VarStatus::undeclared:
      return fail(x, ErrorId::NcVarDeclaration, pos,
                  fmt::format("{} is not declared; declare it in #VAR .. #ENDVAR", name));
    case VarStatus::memory_cap:
      return fail(x, ErrorId::NcVariableMemory, pos,
                  fmt::format("the text assigned to {} would take the program's variables past their memory cap",
                              name));
  }
  return false;
}

// Index inside [ ]: integer, >= 0.
bool eval_index(Cursor& c, ExprCtx& x, long long& idx) {
  std::size_t at = c.pos;
  double v = 0;
  c.skip_spaces();
  if (!eval_expr(c, x, v)) return false;
  c.skip_spaces();
  if (!c.match(']')) return fail(x, ErrorId::NcExprSyntax, c.pos, "']' expected to close the index");
  double r = std::round(v);
  if (!std::isfinite(v) || r < 0 || std::fabs(v - r) > 1e-9 || r > 1e9)
    return fail(x, ErrorId::NcIndexOutOfRange, at, fmt::format("index {} is not an integer >= 0", v));
  idx = static_cast<long long>(r);
  return true;
}

// After "V.": scope and name parts into a normalised key.
bool parse_var_key(Cursor& c, ExprCtx& x, std::string& key) {
  std::size_t at = c.pos;
  key = "V.";
  c.pos += 2;
  std::string_view scope = c.read_ident();
  if (scope.empty() || c.peek() != '.')
    return fail(x, ErrorId::NcExprSyntax, at, "variable name expected after V. (e.g. V.L.NAME)");
  key += to_upper(scope);
  for (;;) {
    if (c.peek() == '.' && (is_alpha(c.peek(1)) || c.peek(1) == '_')) {
      ++c.pos;
      key += '.';
      key += to_upper(c.read_ident());
    } else if (c.peek() == '[') {
      ++c.pos;
      long long idx = 0;
      if (!eval_index(c, x, idx)) return false;
      key += fmt::format("[{}]", idx);
    } else {
      break;
    }
  }
  if (key.size() <= scope.size() + 3)
    return fail(x, ErrorId::NcExprSyntax, at, "variable name expected after the scope (e.g. V.L.NAME)");
  return true;
}

bool call_function(std::string_view name, const double* a, int n, std::size_t pos, ExprCtx& x,
                   double& out) {
  auto need = [&](int k) {
    if (n == k) return true;
    return fail(x, ErrorId::NcExprSyntax, pos,
                fmt::format("{} takes {} argument(s), {} given", name, k, n));
  };
  auto domain = [&](const char* what) {
    return fail(x, ErrorId::NcMathDomain, pos, fmt::format("{}: {}", name, what));
  };
  std::string up = to_upper(name);
  if (up == "SIN") { if (!need(1)) return false; out = std::sin(a[0] * kDeg); }
  else if (up == "COS") { if (!need(1)) return false; out = std::cos(a[0] * kDeg); }
  else if (up == "TAN") {
    if (!need(1)) return false;
    if (std::fabs(std::cos(a[0] * kDeg)) < 1e-15) return domain("tangent of 90 degrees is infinite");
    out = std::tan(a[0] * kDeg);
  } else if (up == "ASIN" || up == "ACOS") {
    if (!need(1)) return false;
    if (a[0] < -1 || a[0] > 1) return domain("argument must be between -1 and 1");
    out = (up == "ASIN" ? std::asin(a[0]) : std::acos(a[0])) / kDeg;
  } else if (up == "ATAN") {
    if (n == 2) out = std::atan2(a[0], a[1]) / kDeg;
    else { if (!need(1)) return false; out = std::atan(a[0]) / kDeg; }
  } else if (up == "ATAN2") { if (!need(2)) return false; out = std::atan2(a[0], a[1]) / kDeg; }
  else if (up == "SQRT") {
    if (!need(1)) return false;
    if (a[0] < 0) return domain("square root of a negative number");
    out = std::sqrt(a[0]);
  } else if (up == "SQR") { if (!need(1)) return false; out = a[0] * a[0]; }
  else if (up == "ABS") { if (!need(1)) return false; out = std::fabs(a[0]); }
  else if (up == "INT" || up == "TRUNC") { if (!need(1)) return false; out = std::trunc(a[0]); }
  else if (up == "FRACT") { if (!need(1)) return false; out = a[0] - std::trunc(a[0]); }
  else if (up == "ROUND") { if (!need(1)) return false; out = std::round(a[0]); }
  else if (up == "CEIL") { if (!need(1)) return false; out = std::ceil(a[0]); }
  else if (up == "FLOOR") { if (!need(1)) return false; out = std::floor(a[0]); }
  else if (up == "SIGN") { if (!need(1)) return false; out = (a[0] > 0) - (a[0] < 0); }
  else if (up == "EXP") { if (!need(1)) return false; out = std::exp(a[0]); }
  else if (up == "DEXP") { if (!need(1)) return false; out = std::pow(10.0, a[0]); }
  else if (up == "LN" || up == "LOG") {
    if (!need(1)) return false;
    if (a[0] <= 0) return domain("logarithm of a number <= 0");
    out = up == "LN" ? std::log(a[0]) : std::log10(a[0]);
  } else if (up == "POW") {
    if (!need(2)) return false;
    out = std::pow(a[0], a[1]);
    if (!std::isfinite(out)) return domain("result is not a real number");
  } else if (up == "MOD") {
    if (!need(2)) return false;
    if (a[1] == 0) return fail(x, ErrorId::NcDivisionByZero, pos, "MOD by 0");
    out = std::fmod(a[0], a[1]);
  } else if (up == "MIN") { if (!need(2)) return false; out = std::fmin(a[0], a[1]); }
  else if (up == "MAX") { if (!need(2)) return false; out = std::fmax(a[0], a[1]); }
  else if (isg_expression_function(up)) {
    return fail(x, ErrorId::NcUnsupported, pos, fmt::format("{} is an ISG function nck does not support", up));
  } else {
    return fail(x, ErrorId::NcUnknownFunction, pos, fmt::format("unknown function {}", name));
  }
  return true;
}

bool eval_primary(Cursor& c, ExprCtx& x, double& out) {
  c.skip_spaces();
  std::size_t at = c.pos;
  char ch = c.peek();
  if (is_digit(ch) || ch == '.') {
    if (!c.read_number(out)) return fail(x, ErrorId::NcBadValue, at, "malformed number");
    return true;
  }
  if (ch == '[') {
    ++c.pos;
    if (!eval_expr(c, x, out)) return false;
    c.skip_spaces();
    if (!c.match(']'))
      return fail(x, ErrorId::NcExprSyntax, c.pos, "']' expected: the bracket opened here is not closed");
    return true;
  }
  if (ch == '"') return fail(x, ErrorId::NcTypeMismatch, at, "a string cannot be used as a number");
  if (looks_like_lvalue(c)) {
    Lvalue lv;
    if (!parse_lvalue(c, x, lv)) return false;
    return read_lvalue(lv, x, out);
  }
  if (ch == '@')
    return fail(x, ErrorId::NcCycleWord, at, "only @P<n> and @P[<expr>] have a value in an expression");
  if (is_alpha(ch)) {
    std::string_view id = c.read_ident();
    if (iequals(id, "TRUE")) { out = 1; return true; }
    if (iequals(id, "FALSE")) { out = 0; return true; }
    if (iequals(id, "PI")) { out = 3.14159265358979323846; return true; }
    if (iequals(id, "EXIST")) {
      c.skip_spaces();
      if (!c.match('[')) return fail(x, ErrorId::NcExprSyntax, c.pos, "EXIST needs [ ]");
      c.skip_spaces();
      Lvalue lv;
      ErrorSlot probe;
      ExprCtx px{x.vars, probe, x.depth};
      double tmp = 0;
      out = (parse_lvalue(c, px, lv) && read_lvalue(lv, px, tmp)) ? 1 : 0;
      while (!c.at_end() && c.peek() != ']') ++c.pos;  // skip what EXIST could not read
      if (!c.match(']')) return fail(x, ErrorId::NcExprSyntax, c.pos, "']' expected after EXIST[..");
      return true;
    }
    c.skip_spaces();
    if (!c.match('['))
      return fail(x, ErrorId::NcUnknownFunction, at,
                  fmt::format("'{}' is neither a function nor a value", id));
    double args[4];
    int n = 0;
    for (;;) {
      double v = 0;
      if (!eval_expr(c, x, v)) return false;
      if (n < 4) args[n] = v;
      ++n;
      c.skip_spaces();
      if (c.match(',')) continue;
      if (c.match(']')) break;
      return fail(x, ErrorId::NcExprSyntax, c.pos, "',' or ']' expected in the argument list");
    }
    if (n > 4) return fail(x, ErrorId::NcExprSyntax, at, "too many arguments");
    return call_function(id, args, n, at, x, out);
  }
  if (c.at_end()) return fail(x, ErrorId::NcExprSyntax, at, "value expected but the block ends");
  return fail(x, ErrorId::NcExprSyntax, at, fmt::format("value expected, found '{}'", ch));
}

bool eval_unary(Cursor& c, ExprCtx& x, double& out) {
  if (++x.depth > kMaxDepth) {
    --x.depth;
    return fail(x, ErrorId::NcExprTooDeep, c.pos,
                fmt::format("the expression nests more than {} brackets or operators deep; split it", kMaxDepth));
  }
  c.skip_spaces();
  bool ok;
  if (c.match('-')) {
    ok = eval_unary(c, x, out);
    out = -out;
  } else if (c.match('+')) {
    ok = eval_unary(c, x, out);
  } else if ((c.peek() == '!' && c.peek(1) != '=') || c.peek_keyword("NOT")) {
    if (!c.match('!')) c.pos += 3;
    ok = eval_unary(c, x, out);
    out = (out == 0) ? 1 : 0;
  } else {
    ok = eval_primary(c, x, out);
    if (ok) {
      c.skip_spaces();
      if (c.peek() == '*' && c.peek(1) == '*') {
        c.pos += 2;
        double e = 0;
        ok = eval_unary(c, x, e);
        out = std::pow(out, e);
        if (ok && !std::isfinite(out))
          ok = fail(x, ErrorId::NcMathDomain, c.pos, "power: result is not a real number");
      }
    }
  }
  --x.depth;
  return ok;
}

bool eval_mul(Cursor& c, ExprCtx& x, double& out) {
  if (!eval_unary(c, x, out)) return false;
  for (;;) {
    c.skip_spaces();
    std::size_t at = c.pos;
    char op = c.peek();
    bool mod = false;
    if (op == '*' && c.peek(1) != '*') ++c.pos;
    else if (op == '/') ++c.pos;
    else if (c.match_keyword("MOD")) mod = true;
    else return true;
    double r = 0;
    if (!eval_unary(c, x, r)) return false;
    if (op == '*' && !mod) { out *= r; continue; }
    if (r == 0)
      return fail(x, ErrorId::NcDivisionByZero, at,
                  mod ? "MOD by 0: the right operand is 0" : "division by 0: the divisor is 0");
    out = mod ? std::fmod(out, r) : out / r;
  }
}

bool eval_add(Cursor& c, ExprCtx& x, double& out) {
  if (!eval_mul(c, x, out)) return false;
  for (;;) {
    c.skip_spaces();
    char op = c.peek();
    if (op != '+' && op != '-') return true;
    ++c.pos;
    double r = 0;
    if (!eval_mul(c, x, r)) return false;
    out = op == '+' ? out + r : out - r;
  }
}

bool eval_cmp(Cursor& c, ExprCtx& x, double& out) {
  if (!eval_add(c, x, out)) return false;
  c.skip_spaces();
  int op = 0;  // 1 == 2 != 3 < 4 <= 5 > 6 >=
  char a = c.peek(), b = c.peek(1);
  if (a == '=' && b == '=') { op = 1; c.pos += 2; }
  else if (a == '!' && b == '=') { op = 2; c.pos += 2; }
  else if (a == '<' && b == '>') { op = 2; c.pos += 2; }
  else if (a == '<' && b == '=') { op = 4; c.pos += 2; }
  else if (a == '>' && b == '=') { op = 6; c.pos += 2; }
  else if (a == '<') { op = 3; ++c.pos; }
  else if (a == '>') { op = 5; ++c.pos; }
  if (!op) return true;
  double r = 0;
  if (!eval_add(c, x, r)) return false;
  constexpr double eps = 1e-9;  // tolerate binary rounding in == tests
  bool res = false;
  switch (op) {
    case 1: res = std::fabs(out - r) <= eps; break;
    case 2: res = std::fabs(out - r) > eps; break;
    case 3: res = out < r; break;
    case 4: res = out <= r + eps; break;
    case 5: res = out > r; break;
    case 6: res = out + eps >= r; break;
  }
  out = res ? 1 : 0;
  return true;
}

bool eval_and(Cursor& c, ExprCtx& x, double& out) {
  if (!eval_cmp(c, x, out)) return false;
  for (;;) {
    c.skip_spaces();
    if (c.peek() == '&' && c.peek(1) == '&') c.pos += 2;
    else if (!c.match_keyword("AND")) return true;
    double r = 0;
    if (!eval_cmp(c, x, r)) return false;
    out = (out != 0 && r != 0) ? 1 : 0;
  }
}

bool eval_or(Cursor& c, ExprCtx& x, double& out) {
  if (!eval_and(c, x, out)) return false;
  for (;;) {
    c.skip_spaces();
    bool is_xor = false;
    if (c.peek() == '|' && c.peek(1) == '|') c.pos += 2;
    else if (c.match_keyword("OR")) {}
    else if (c.match_keyword("XOR")) is_xor = true;
    else return true;
    double r = 0;
    if (!eval_and(c, x, r)) return false;
    out = is_xor ? (((out != 0) != (r != 0)) ? 1 : 0) : ((out != 0 || r != 0) ? 1 : 0);
  }
}

}  // namespace

bool eval_expr(Cursor& c, ExprCtx& x, double& out) {
  if (++x.depth > kMaxDepth) {
    --x.depth;
    return fail(x, ErrorId::NcExprTooDeep, c.pos,
                fmt::format("the expression nests more than {} brackets or operators deep; split it", kMaxDepth));
  }
  bool ok = eval_or(c, x, out);
  --x.depth;
  if (ok && !std::isfinite(out))
    return fail(x, ErrorId::NcMathDomain, c.pos, "the expression's result is not a finite number");
  return ok;
}

bool eval_value(Cursor& c, ExprCtx& x, double& out) {
  bool ok = eval_unary(c, x, out);
  if (ok && !std::isfinite(out))
    return fail(x, ErrorId::NcMathDomain, c.pos, "the value is not a finite number");
  return ok;
}

namespace {

// The manual numbers transfer parameters @P1..@P200.
bool check_cycle_index(const Lvalue& lv, ExprCtx& x) {
  if (lv.p >= 1 && lv.p <= 200) return true;
  return fail(x, ErrorId::NcCycleWord, lv.pos, fmt::format("@P{} is not a transfer parameter (@P1..@P200)", lv.p));
}

bool cycle_outside(const Lvalue& lv, ExprCtx& x) {
  return fail(x, ErrorId::NcCycleParamOutsideCycle, lv.pos,
              fmt::format("@P{} belongs to a cycle: read or write it only inside the cycle or in its call", lv.p));
}

}  // namespace

bool looks_like_lvalue(const Cursor& c) {
  char a = upper(c.peek()), b = c.peek(1);
  if (a == 'P' && (is_digit(b) || b == '[')) return true;
  if (a == '@' && upper(b) == 'P' && (is_digit(c.peek(2)) || c.peek(2) == '[')) return true;
  return a == 'V' && b == '.' && (is_alpha(c.peek(2)) || c.peek(2) == '_');
}

bool parse_lvalue(Cursor& c, ExprCtx& x, Lvalue& lv) {
  lv.pos = c.pos;
  if (c.peek() == '@' && upper(c.peek(1)) == 'P') {
    ++c.pos;
    lv.is_cycle_p = true;
  }
  if (upper(c.peek()) == 'P') {
    ++c.pos;
    lv.is_p = true;
    if (c.match('[')) {
      long long idx = 0;
      if (!eval_index(c, x, idx)) return false;
      lv.p = idx;
      return !lv.is_cycle_p || check_cycle_index(lv, x);
    }
    std::int64_t v = 0;
    int n = 0;
    while (is_digit(c.peek())) {
      v = v * 10 + (c.get() - '0');
      if (++n > 9) return fail(x, ErrorId::NcBadValue, lv.pos, "P parameter number too large");
    }
    if (n == 0) return fail(x, ErrorId::NcBadValue, lv.pos, "P parameter number expected");
    lv.p = v;
    if (lv.is_cycle_p) return check_cycle_index(lv, x);
    return true;
  }
  if (upper(c.peek()) == 'V' && c.peek(1) == '.') return parse_var_key(c, x, lv.key);
  return fail(x, ErrorId::NcExprSyntax, c.pos, "P parameter or V. variable expected");
}

bool read_lvalue(const Lvalue& lv, ExprCtx& x, double& out) {
  if (lv.is_cycle_p) {
    const VarStatus s = x.vars.read_cycle_p(lv.p, out);
    if (s == VarStatus::ok) return true;
    if (s == VarStatus::undefined)
      return fail(x, ErrorId::NcCycleParamMissing, lv.pos,
                  fmt::format("the cycle reads @P{}, which its call does not give", lv.p));
    return cycle_outside(lv, x);
  }
  if (lv.is_p) {
    if (x.vars.read_p(lv.p, out) == VarStatus::ok) return true;
    return fail(x, ErrorId::NcUndefinedVariable, lv.pos,
                fmt::format("P{} has no value yet; assign it first (P{} = ..)", lv.p, lv.p));
  }
  return status_error(x, x.vars.read(lv.key, out), lv.pos, lv.key);
}

bool write_lvalue(const Lvalue& lv, ExprCtx& x, double v) {
  if (lv.is_cycle_p) return x.vars.write_cycle_p(lv.p, v) == VarStatus::ok || cycle_outside(lv, x);
  if (lv.is_p) {
    x.vars.write_p(lv.p, v);
    return true;
  }
  return status_error(x, x.vars.write(lv.key, v), lv.pos, lv.key);
}

}  // namespace nck::nc::detail
