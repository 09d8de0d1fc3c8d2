// Parser driver: version statement, statement loop with line-based error recovery, and
// the public entry points parse_program() / parse_text().
#include "tierlift/assembly/parser.h"

#include <fmt/format.h>

#include "parser_impl.h"

namespace tierlift::assembly {
namespace detail {
namespace {
// Past this many errors the rest of a listing is not worth reporting.
constexpr size_t kMaxErrors = 100;
} // namespace

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

void Parser::skip_line() {
  while (!at_eol()) advance();
}

bool Parser::fail(ir::SourceLoc loc, std::string rule, std::string message) {
  diags_.error(loc, std::move(rule), std::move(message));
  return false;
}

std::string Parser::describe(const Token& t) const {
  if (t.kind == TokKind::Newline || t.kind == TokKind::End) return "end of line";
  return fmt::format("'{}'", t.text);
}

// A location from `start` to the end of the token before the cursor (same line only).
ir::SourceLoc Parser::span_to_prev(ir::SourceLoc start) const {
  if (pos_ == 0) return start;
  const ir::SourceLoc& last = toks_[pos_ - 1].loc;
  if (last.file == start.file && last.line == start.line && last.col >= start.col)
    start.length = last.col + last.length - start.col;
  return start;
}

bool Parser::version() {
  while (cur().kind == TokKind::Newline) advance();
  const Token& t = cur();
  if (t.kind == TokKind::End) {
    ir::SourceLoc loc = t.loc;
    if (!loc.valid()) loc = {main_file_, 1, 1, 0};
    return fail(loc, "missing-version",
                "missing version statement: a listing starts with vs_1_1, vs_2_0, vs_2_x, vs_3_0, "
                "ps_1_1 ... ps_2_0, ps_2_x or ps_3_0");
  }
  if (t.kind == TokKind::Ident) {
    std::string name = lower(t.text);
    if (auto p = ir::parse_profile(name)) {
      prog_.profile = *p;
      prog_.version_loc = t.loc;
      advance();
      return true;
    }
    if (name.size() > 2 && (name.starts_with("vs") || name.starts_with("ps")) &&
        (name[2] == '_' || name[2] == '.'))
      return fail(t.loc, "unsupported-version",
                  fmt::format("unsupported shader version '{}' (supported: vs_1_1, vs_2_0, "
                              "vs_2_x, vs_3_0, ps_1_1, ps_1_2, ps_1_3, ps_1_4, ps_2_0, ps_2_x, "
                              "ps_3_0)",
                              t.text));
  }
  return fail(t.loc, "missing-version",
              fmt::format("missing version statement before {}: a listing starts with vs_1_1, "
                          "vs_2_0, vs_2_x, vs_3_0, ps_1_1 ... ps_2_0, ps_2_x or ps_3_0",
                          describe(t)));
}

std::optional<ir::Program> Parser::run() {
  if (!version()) return std::nullopt;
  while (true) {
    while (cur().kind == TokKind::Newline) advance();
    if (cur().kind == TokKind::End) break;
    if (diags_.error_count() - first_error_ >= kMaxErrors) {
      diags_.note(cur().loc, "too-many-errors", "too many errors; parsing stopped");
      break;
    }
    // Recovery: a statement that fails is dropped with the rest of its line.
    if (!statement()) skip_line();
    // Another statement may follow on the same line (the D3DX grammar ignores line ends).
    continued_ = !at_eol();
  }
  if (diags_.error_count() > first_error_) return std::nullopt;
  return std::move(prog_);
}

bool Parser::statement() {
  if (at_punct(kCommentBlockMark)) return comment_block();
  bool coissue = false;
  if (at_punct("+")) {
    coissue = true;
    advance();
    // "mul r0.rgb, r0, t0 +" / "mov r0.a, t1": the '+' that pairs two instructions may end
    // the first line instead of starting the second (Microsoft's assembler reads statements,
    // not lines). One '+' pairs them however it is placed; a second one is the same mark.
    while (cur().kind == TokKind::Newline) advance();
    if (at_punct("+")) advance();
  }
  std::optional<ir::SrcOperand> pred;
  if (!coissue && at_punct("(")) {
    pred.emplace();
    if (!predicate(*pred)) return false;
  }
  const Token& mn = cur();
  if (mn.kind != TokKind::Ident)
    return fail(mn.loc, "syntax", fmt::format("expected an instruction, found {}", describe(mn)));
  advance();
  std::string name = lower(mn.text);
  if (ir::parse_profile(name))
    return fail(mn.loc, "syntax", "the version statement must come first and only once");
  // Some disassemblers write the comparison forms as ifc_gt / breakc_gt: the same rows.
  if (name.starts_with("ifc_")) name.erase(2, 1);
  if (name.starts_with("breakc_")) name.erase(5, 1);
  std::string_view base = name, mods;
  if (size_t us = name.find('_'); us != std::string::npos) {
    base = std::string_view(name).substr(0, us);
    mods = std::string_view(name).substr(us); // keeps the leading '_'
    // if_gt, break_ne, setp_le: the comparison is part of the mnemonic, not a modifier.
    size_t next = name.find('_', us + 1);
    std::string_view with_cmp = std::string_view(name).substr(0, next);
    if (!ir::rows_for_mnemonic(with_cmp).empty()) {
      base = with_cmp;
      mods = next == std::string::npos ? std::string_view() : std::string_view(name).substr(next);
    }
  }
  if (pred) {
    if (base == "dcl" || base == "def" || base == "defi" || base == "defb")
      return fail(pred->loc, "syntax", "a declaration or definition cannot be predicated");
    return instruction(mn, base, mods, false, std::move(pred));
  }
  if (!coissue) {
    if (base == "dcl") return declaration(mn, mods);
    if (base == "def" && mods.empty()) return definition(mn, ir::Opcode::Def);
    if (base == "defi" && mods.empty()) return definition(mn, ir::Opcode::DefI);
    if (base == "defb" && mods.empty()) return definition(mn, ir::Opcode::DefB);
  }
  return instruction(mn, base, mods, coissue);
}

} // namespace detail

std::optional<ir::Program> parse_program(uint32_t file, ir::SourceManager& sm,
                                         ir::DiagnosticSink& diags, const ParseOptions& options) {
  size_t errors_before = diags.error_count();
  try {
    TokenStream ts = preprocess(file, sm, diags, options);
    if (ts.binary) return std::nullopt;
    detail::Parser parser(ts, diags, file, options.strict);
    auto program = parser.run();
    if (diags.error_count() > errors_before) return std::nullopt;
    return program;
  } catch (const std::exception& e) {
    // Only resource exhaustion or a file-system failure can get here; never let it escape.
    diags.error({file, 0, 0, 0}, "internal", fmt::format("parser failed: {}", e.what()));
    return std::nullopt;
  }
}

ParseResult parse_text(std::string text, std::string name, const ParseOptions& options) {
  ParseResult r;
  uint32_t id = r.sources.add(std::move(name), std::move(text));
  r.program = parse_program(id, r.sources, r.diags, options);
  return r;
}

} // namespace tierlift::assembly
