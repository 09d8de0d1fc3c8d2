// Recursive-descent evaluator for #if expressions. Arithmetic is done on uint64_t and
// reinterpreted, so overflow wraps instead of being undefined; recursion is bounded.
#include "pp_expr.h"

#include <charconv>
#include <string>

#include <fmt/format.h>

namespace tierlift::assembly::detail {
namespace {

constexpr int kMaxDepth = 200;

class ExprParser {
public:
  ExprParser(std::span<const Token> toks, ir::SourceLoc where, ir::DiagnosticSink& diags)
      : toks_(toks), where_(where), diags_(diags) {}

  std::optional<int64_t> run() {
    if (toks_.empty()) return fail(where_, "#if with no expression");
    int64_t v = conditional(0);
    if (failed_) return std::nullopt;
    if (pos_ < toks_.size())
      return fail(toks_[pos_].loc,
                  fmt::format("unexpected '{}' in #if expression", toks_[pos_].text));
    return v;
  }

private:
  std::optional<int64_t> fail(ir::SourceLoc loc, std::string msg) {
    if (!failed_) diags_.error(loc, "preprocessor", std::move(msg));
    failed_ = true;
    return std::nullopt;
  }
  bool at(std::string_view p) const {
    return pos_ < toks_.size() && toks_[pos_].kind == TokKind::Punct && toks_[pos_].text == p;
  }
  bool accept(std::string_view p) {
    if (!at(p)) return false;
    ++pos_;
    return true;
  }
  ir::SourceLoc here() const { return pos_ < toks_.size() ? toks_[pos_].loc : where_; }

  static int64_t wrap(uint64_t u) { return static_cast<int64_t>(u); }
  static uint64_t u(int64_t v) { return static_cast<uint64_t>(v); }

  int64_t conditional(int depth) {
    if (depth > kMaxDepth) return fail(here(), "#if expression nested too deeply"), 0;
    int64_t c = binary(0, depth);
    if (failed_ || !accept("?")) return c;
    int64_t a = conditional(depth + 1);
    if (!accept(":")) return fail(here(), "expected ':' in #if expression"), 0;
    int64_t b = conditional(depth + 1);
    return c ? a : b;
  }

  static int precedence(std::string_view op) {
    static constexpr std::pair<std::string_view, int> table[] = {
        {"||", 1}, {"&&", 2}, {"|", 3}, {"^", 4},  {"&", 5},  {"==", 6},
        {"!=", 6}, {"<", 7},  {">", 7}, {"<=", 7}, {">=", 7}, {"<<", 8},
        {">>", 8}, {"+", 9},  {"-", 9}, {"*", 10}, {"/", 10}, {"%", 10}};
    for (auto& [name, prec] : table)
      if (name == op) return prec;
    return -1;
  }

  // Precedence climbing: loops over operators of equal level, recurses one level up.
  int64_t binary(int min_prec, int depth) {
    int64_t lhs = unary(depth + 1);
    while (!failed_ && pos_ < toks_.size() && toks_[pos_].kind == TokKind::Punct) {
      const Token& op = toks_[pos_];
      int prec = precedence(op.text);
      if (prec < 0 || prec < min_prec) break;
      ++pos_;
      int64_t rhs = binary(prec + 1, depth + 1);
      if (failed_) return 0;
      lhs = apply(op, lhs, rhs);
    }
    return lhs;
  }

  int64_t apply(const Token& op, int64_t a, int64_t b) {
    std::string_view o = op.text;
    if (o == "||") return (a || b) ? 1 : 0;
    if (o == "&&") return (a && b) ? 1 : 0;
    if (o == "|") return a | b;
    if (o == "^") return a ^ b;
    if (o == "&") return a & b;
    if (o == "==") return a == b;
    if (o == "!=") return a != b;
    if (o == "<") return a < b;
    if (o == ">") return a > b;
    if (o == "<=") return a <= b;
    if (o == ">=") return a >= b;
    if (o == "<<") return wrap(u(a) << (u(b) & 63));
    if (o == ">>")
      return a >> (u(b) & 63); // arithmetic shift of a signed value is defined in C++20
    if (o == "+") return wrap(u(a) + u(b));
    if (o == "-") return wrap(u(a) - u(b));
    if (o == "*") return wrap(u(a) * u(b));
    if (b == 0) return fail(op.loc, "division by zero in #if expression"), 0;
    if (a == INT64_MIN && b == -1) return o == "/" ? a : 0;
    return o == "/" ? a / b : a % b;
  }

  int64_t unary(int depth) {
    if (depth > kMaxDepth) return fail(here(), "#if expression nested too deeply"), 0;
    if (accept("!")) return unary(depth + 1) == 0 ? 1 : 0;
    if (accept("~")) return ~unary(depth + 1);
    if (accept("-")) return wrap(0 - u(unary(depth + 1)));
    if (accept("+")) return unary(depth + 1);
    if (accept("(")) {
      int64_t v = conditional(depth + 1);
      if (!failed_ && !accept(")")) return fail(here(), "expected ')' in #if expression"), 0;
      return v;
    }
    if (pos_ >= toks_.size()) return fail(where_, "#if expression ends too early"), 0;
    const Token& t = toks_[pos_++];
    if (t.kind == TokKind::Ident) return t.text == "true" ? 1 : 0; // undefined names are 0
    if (t.kind == TokKind::Number) return number(t);
    return fail(t.loc, fmt::format("unexpected '{}' in #if expression", t.text)), 0;
  }

  int64_t number(const Token& t) {
    std::string_view s = t.text;
    while (!s.empty() && (s.back() == 'u' || s.back() == 'U' || s.back() == 'l' || s.back() == 'L'))
      s.remove_suffix(1);
    int base = 10;
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X'))
      base = 16, s.remove_prefix(2);
    else if (s.size() > 1 && s[0] == '0')
      base = 8, s.remove_prefix(1);
    uint64_t v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v, base);
    if (ec != std::errc() || p != s.data() + s.size())
      return fail(t.loc, fmt::format("'{}' is not an integer in #if expression", t.text)), 0;
    return wrap(v);
  }

  std::span<const Token> toks_;
  ir::SourceLoc where_;
  ir::DiagnosticSink& diags_;
  size_t pos_ = 0;
  bool failed_ = false;
};

} // namespace

std::optional<int64_t> eval_pp_expression(std::span<const Token> tokens, ir::SourceLoc where,
                                          ir::DiagnosticSink& diags) {
  return ExprParser(tokens, where, diags).run();
}

} // namespace tierlift::assembly::detail
