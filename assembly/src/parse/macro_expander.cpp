// Macro expansion. Bounded on every axis a fuzzer could push: nesting depth, tokens
// produced per line (so "#define A B B" chains cannot explode), and no self-expansion.
#include <algorithm>

#include <fmt/format.h>

#include "macros.h"

namespace tierlift::assembly::detail {
namespace {

constexpr int kMaxDepth = 64;
constexpr size_t kMaxTokensPerLine = 1u << 14; // far beyond any real statement
// All expansions of one listing together: stops "billion laughs" spread over many lines.
constexpr size_t kMaxTokensTotal = 1u << 22;

bool is_punct(const Token& t, std::string_view p) {
  return t.kind == TokKind::Punct && t.text == p;
}

// "_bx2", "_sat_x2": every '_'-separated part is a source or instruction modifier.
bool is_modifier_suffix(std::string_view s) {
  static constexpr std::string_view kWords[] = {"bias", "bx2", "x2",  "dz",      "db", "dw",
                                                "da",   "abs", "sat", "pp",      "x4", "x8",
                                                "d2",   "d4",  "d8",  "centroid"};
  if (s.size() < 2 || s[0] != '_') return false;
  for (size_t i = 1; i <= s.size();) {
    size_t end = std::min(s.find('_', i), s.size());
    std::string word(s.substr(i, end - i));
    for (char& c : word)
      if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (std::find(std::begin(kWords), std::end(kWords), word) == std::end(kWords)) return false;
    i = end + 1;
  }
  return true;
}

} // namespace

// Microsoft's assembler expands a macro written with a modifier glued on ("#define TEX t0",
// then "TEX_bx2"), although C would read TEX_bx2 as one unknown name. The split is the
// longest prefix that names an object-like macro, and only when all that follows it is
// modifiers, so an identifier that merely contains a macro's name is left alone.
size_t MacroTable::modifier_split(std::string_view name) const {
  // The longest modifier run ("_sat_x2_bx2") is far shorter than this; the bound keeps a
  // name made of thousands of '_' parts linear.
  constexpr size_t kMaxSuffix = 32;
  for (size_t us = name.rfind('_');
       us != std::string_view::npos && us > 0 && name.size() - us <= kMaxSuffix;
       us = name.rfind('_', us - 1)) {
    if (!is_modifier_suffix(name.substr(us))) continue;
    auto it = macros_.find(name.substr(0, us));
    if (it != macros_.end() && !it->second.function_like && !it->second.active) return us;
  }
  return std::string_view::npos;
}

// Expands the macro part of `t` (split at `us`) and glues the modifier onto what it gives:
// "t0" + "_bx2" -> "t0_bx2"; "c[a0.x + 1]" + "_bx2" -> "c[a0.x + 1]" "_bx2", which the operand
// parser reads as a modifier after the brackets. False when the expansion ends in anything
// else, so the caller reports the name as it stands.
bool MacroTable::expand_with_modifier(const Token& t, size_t us, std::vector<Token>& out,
                                      const ir::SourceLoc* use, int depth) {
  Token head = t;
  head.text = t.text.substr(0, us);
  std::vector<Token> expanded;
  if (!expand_impl(std::span<const Token>(&head, 1), expanded, use, depth)) return false;
  if (expanded.empty()) return false;
  Token& last = expanded.back();
  std::string_view suffix = t.text.substr(us);
  if (last.kind == TokKind::Ident) {
    storage_->push_back(
        std::make_unique<std::string>(std::string(last.text) + std::string(suffix)));
    last.text = *storage_->back();
  } else if (is_punct(last, "]")) {
    Token mod = last;
    mod.kind = TokKind::Ident;
    mod.text = suffix;
    mod.space_before = false;
    expanded.push_back(mod);
  } else {
    return false;
  }
  out.insert(out.end(), expanded.begin(), expanded.end());
  return true;
}

bool MacroTable::expand(std::span<const Token> in, std::vector<Token>& out,
                        ir::DiagnosticSink& diags) {
  if (macros_.empty()) { // fast path for the common case: no macros at all
    out.insert(out.end(), in.begin(), in.end());
    return true;
  }
  diags_ = &diags;
  budget_ = kMaxTokensPerLine;
  return expand_impl(in, out, nullptr, 0);
}

bool MacroTable::push(std::vector<Token>& out, Token t, const ir::SourceLoc* use) {
  if (use) { // only tokens that come out of a macro count against the budgets
    if (budget_ == 0 || total_used_ >= kMaxTokensTotal) return false;
    --budget_;
    ++total_used_;
    t.loc = *use;
  }
  out.push_back(t);
  return true;
}

bool MacroTable::expand_impl(std::span<const Token> in, std::vector<Token>& out,
                             const ir::SourceLoc* use, int depth) {
  for (size_t i = 0; i < in.size(); ++i) {
    const Token& t = in[i];
    auto it = t.kind == TokKind::Ident ? macros_.find(t.text) : macros_.end();
    if (it == macros_.end() && t.kind == TokKind::Ident) {
      size_t us = modifier_split(t.text);
      if (us != std::string_view::npos && expand_with_modifier(t, us, out, use, depth)) continue;
    }
    if (it == macros_.end() || it->second.active ||
        (it->second.function_like && (i + 1 >= in.size() || !is_punct(in[i + 1], "(")))) {
      if (!push(out, t, use)) {
        diags_->error(t.loc, "preprocessor", "macro expansion produces too many tokens");
        return false;
      }
      continue;
    }
    Macro& m = it->second;
    ir::SourceLoc loc = use ? *use : t.loc;
    if (depth >= kMaxDepth) {
      diags_->error(loc, "preprocessor", fmt::format("macro '{}' nests too deeply", t.text));
      return false;
    }
    std::vector<Token> subst;
    if (m.function_like) {
      if (!substitute_call(m, in, i, loc, depth, subst)) return false;
    } else {
      subst = m.body;
    }
    paste(subst);
    if (!subst.empty()) subst.front().space_before = t.space_before;
    m.active = true;
    bool ok = expand_impl(subst, out, &loc, depth + 1);
    m.active = false;
    if (!ok) return false;
  }
  return true;
}

// a ## b → one token "ab" (kept in the stream's storage, so it outlives the macro table).
void MacroTable::paste(std::vector<Token>& toks) {
  std::vector<Token> out;
  for (size_t i = 0; i < toks.size(); ++i) {
    if (!is_punct(toks[i], "##") || out.empty() || i + 1 >= toks.size()) {
      if (!is_punct(toks[i], "##")) out.push_back(toks[i]);
      continue;
    }
    Token& left = out.back();
    const Token& right = toks[++i];
    storage_->push_back(
        std::make_unique<std::string>(std::string(left.text) + std::string(right.text)));
    std::string_view text = *storage_->back();
    auto ident_char = [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    };
    bool ident = std::all_of(text.begin(), text.end(), ident_char);
    bool number = !text.empty() && ((text[0] >= '0' && text[0] <= '9') || text[0] == '.');
    left.kind = number ? TokKind::Number : ident ? TokKind::Ident : TokKind::Punct;
    left.text = text;
  }
  toks = std::move(out);
}

// in[i] is the macro name, in[i + 1] is "(". On success i points at the closing ")".
bool MacroTable::substitute_call(const Macro& m, std::span<const Token> in, size_t& i,
                                 ir::SourceLoc loc, int depth, std::vector<Token>& subst) {
  std::string_view name = in[i].text;
  std::vector<std::vector<Token>> args(1);
  int level = 0;
  size_t j = i + 2;
  bool closed = false;
  for (; j < in.size(); ++j) {
    const Token& a = in[j];
    if (is_punct(a, "(")) ++level;
    if (is_punct(a, ")")) {
      if (level == 0) {
        closed = true;
        break;
      }
      --level;
    }
    if (is_punct(a, ",") && level == 0) {
      args.emplace_back();
      continue;
    }
    args.back().push_back(a);
  }
  if (!closed) {
    diags_->error(loc, "preprocessor", fmt::format("unterminated call of macro '{}'", name));
    return false;
  }
  if (m.params.empty() && args.size() == 1 && args[0].empty()) args.clear();
  if (args.size() != m.params.size()) {
    diags_->error(
        loc, "preprocessor",
        fmt::format("macro '{}' takes {} argument(s), got {}", name, m.params.size(), args.size()));
    return false;
  }
  // Arguments are fully expanded before substitution, as in C.
  std::vector<std::vector<Token>> expanded(args.size());
  for (size_t k = 0; k < args.size(); ++k)
    if (!expand_impl(args[k], expanded[k], &loc, depth + 1)) return false;
  for (size_t bi = 0; bi < m.body.size(); ++bi) {
    const Token& b = m.body[bi];
    size_t k = 0;
    while (k < m.params.size() && !(b.kind == TokKind::Ident && b.text == m.params[k])) ++k;
    // Next to ## an argument is pasted as written, not expanded (C rule).
    bool pasted = (bi > 0 && is_punct(m.body[bi - 1], "##")) ||
                  (bi + 1 < m.body.size() && is_punct(m.body[bi + 1], "##"));
    if (k < m.params.size()) {
      const std::vector<Token>& arg = pasted ? args[k] : expanded[k];
      subst.insert(subst.end(), arg.begin(), arg.end());
    } else {
      subst.push_back(b);
    }
    if (subst.size() > kMaxTokensPerLine) {
      diags_->error(loc, "preprocessor", "macro expansion produces too many tokens");
      return false;
    }
  }
  i = j;
  return true;
}

} // namespace tierlift::assembly::detail
