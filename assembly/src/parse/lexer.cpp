// Lexer: text of one file → tokens with exact positions (1-based line, 1-based byte column).
// One pass, no backtracking, tokens are views into the text: a 10 MB listing lexes in
// linear time and without copying strings.
#include <fmt/format.h>

#include "tierlift/assembly/preprocessor.h"

namespace tierlift::assembly {
namespace {

// Lexer errors stop being reported after this many, so garbage input cannot flood.
constexpr size_t kMaxLexErrors = 50;

bool is_ident_start(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_digit(unsigned char c) {
  return c >= '0' && c <= '9';
}
bool is_ident_char(unsigned char c) {
  return is_ident_start(c) || is_digit(c);
}

// Length of the well-formed UTF-8 sequence at text[i], or 0 when it is malformed.
size_t utf8_length(std::string_view text, size_t i, uint32_t& cp) {
  auto b = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  unsigned char c = b(i);
  size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 ? 2 : 0;
  if (n == 0 || c >= 0xF5 || i + n > text.size()) return 0;
  cp = c & (0x7F >> n);
  for (size_t k = 1; k < n; ++k) {
    if ((b(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (b(i + k) & 0x3F);
  }
  // Reject overlong forms and surrogates.
  if ((n == 3 && cp < 0x800) || (n == 4 && (cp < 0x10000 || cp > 0x10FFFF)) ||
      (cp >= 0xD800 && cp <= 0xDFFF))
    return 0;
  return n;
}

} // namespace

class LineLexer::Impl {
public:
  Impl(uint32_t file, std::string_view text, ir::DiagnosticSink& diags)
      : file_(file), text_(text), diags_(diags) {}

  bool next_line(std::vector<Token>& out) {
    if (finished_) return false;
    out_ = &out;
    if (!started_) {
      started_ = true;
      // NUL bytes after the text are padding some tools write (one game's dumps end every
      // file with one): the text ends where they start. NUL bytes anywhere else mean a
      // binary file: one clear error instead of a flood of syntax errors.
      text_ = text_.substr(0, text_.find_last_not_of('\0') + 1);
      if (size_t nul = text_.find('\0'); nul != std::string_view::npos) {
        advance_to(nul);
        binary_error("input contains a NUL byte; this looks like a binary file, not assembly");
        return finish(LexStatus::Binary);
      }
    }
    while (pos_ < text_.size()) {
      unsigned char c = static_cast<unsigned char>(text_[pos_]);
      if (line_break_at(pos_)) {
        emit(TokKind::Newline, pos_, 1, space_);
        ++pos_;
        ++line_;
        line_start_ = pos_;
        error_on_line_ = false;
        space_ = true;
        return true;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f') {
        ++pos_;
        space_ = true;
      } else if (c == 0xC2 && pos_ + 1 < text_.size() &&
                 static_cast<unsigned char>(text_[pos_ + 1]) == 0xA0) {
        pos_ += 2; // U+00A0 NO-BREAK SPACE (copied from web pages) is white space
        space_ = true;
      } else if (c == '\\' && splice_line()) {
        space_ = true;
      } else if (size_t mark = comment_block_mark(); mark != 0) {
        // "//!comment 0x...": the words of a token-stream comment block, read as tokens
        // (docs/d3d9-rules.md, "Comment blocks"); any other '//' line is a comment.
        emit(TokKind::Punct, pos_, mark, space_);
        pos_ += mark;
        space_ = false;
      } else if (c == ';' || (c == '/' && peek(1) == '/')) {
        skip_to_newline();
        space_ = true;
      } else if (c == '/' && peek(1) == '*') {
        if (!skip_block_comment()) return stop();
        space_ = true;
      } else {
        if (!lex_token(c, space_)) return finish(LexStatus::Binary);
        space_ = false;
      }
      if (stopped_) return stop();
    }
    emit(TokKind::Newline, pos_, 0, space_); // the last line may lack its '\n'
    finished_ = true;
    return true;
  }

  LexStatus status() const { return status_; }

private:
  bool finish(LexStatus st) {
    status_ = st;
    finished_ = true;
    return false;
  }
  // Lexing cannot go on, but the line read so far is still handed out.
  bool stop() {
    emit(TokKind::Newline, pos_, 0, true);
    status_ = LexStatus::Stopped;
    finished_ = true;
    return true;
  }

  // Length of the "//!comment" mark at pos_, or 0. "//!commentary" is an ordinary comment.
  size_t comment_block_mark() const {
    constexpr std::string_view kMark = kCommentBlockMark;
    if (text_.substr(pos_, kMark.size()) != kMark) return 0;
    size_t end = pos_ + kMark.size();
    return end < text_.size() && is_ident_char(static_cast<unsigned char>(text_[end]))
               ? 0
               : kMark.size();
  }

  char peek(size_t k) const { return pos_ + k < text_.size() ? text_[pos_ + k] : '\0'; }

  // '\n', or a '\r' not followed by '\n': files saved with classic Mac OS line endings
  // (CR only) have lines too (ir::SourceManager::line_text splits them the same way).
  bool line_break_at(size_t i) const {
    return text_[i] == '\n' ||
           (text_[i] == '\r' && (i + 1 >= text_.size() || text_[i + 1] != '\n'));
  }

  ir::SourceLoc loc_at(size_t offset, size_t len) const {
    return {file_, line_, static_cast<uint32_t>(offset - line_start_ + 1),
            static_cast<uint32_t>(len)};
  }

  void emit(TokKind kind, size_t begin, size_t len, bool space) {
    out_->push_back({kind, space, text_.substr(begin, len), loc_at(begin, len)});
  }

  // Moves line bookkeeping forward to `offset` (only used before an early error).
  void advance_to(size_t offset) {
    for (; pos_ < offset; ++pos_)
      if (line_break_at(pos_)) line_start_ = pos_ + 1, ++line_;
  }

  void binary_error(std::string msg) {
    diags_.error(loc_at(pos_, 1), "binary-input", std::move(msg));
    stopped_ = true;
  }

  void error(size_t offset, size_t len, std::string rule, std::string msg) {
    if (error_on_line_) return; // one lexer complaint per line is enough
    error_on_line_ = true;
    if (++errors_ > kMaxLexErrors) {
      diags_.note(loc_at(offset, len), "too-many-errors", "too many errors; lexing stopped");
      stopped_ = true;
      return;
    }
    diags_.error(loc_at(offset, len), std::move(rule), std::move(msg));
  }

  // A backslash that ends a line (white space after it allowed) joins the next line to this
  // one, as in C: "#define REG 1 + 2 +\" / "3 + 4" defines REG as 1 + 2 + 3 + 4, which is
  // how Microsoft's assembler reads it (Wine's d3dcompiler asm tests check c[REG] = c10).
  bool splice_line() {
    size_t p = pos_ + 1;
    while (p < text_.size() &&
           (text_[p] == ' ' || text_[p] == '\t' || (text_[p] == '\r' && !line_break_at(p))))
      ++p;
    if (p >= text_.size() || !line_break_at(p)) return false;
    pos_ = p + 1;
    ++line_;
    line_start_ = pos_;
    return true;
  }

  void skip_to_newline() {
    size_t nl = pos_;
    while (nl < text_.size() && !line_break_at(nl)) ++nl;
    pos_ = nl;
  }

  bool skip_block_comment() {
    size_t open = pos_;
    size_t close = text_.find("*/", pos_ + 2);
    if (close == std::string_view::npos) {
      diags_.error(loc_at(open, 2), "unclosed-comment", "unterminated /* comment");
      return false;
    }
    // Keep line numbers right across the comment's own newlines.
    for (size_t i = pos_; i < close; ++i)
      if (line_break_at(i)) ++line_, line_start_ = i + 1;
    pos_ = close + 2;
    return true;
  }

  bool lex_token(unsigned char c, bool space) {
    size_t begin = pos_;
    if (is_ident_start(c)) {
      while (pos_ < text_.size() && is_ident_char(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      extend_dot_version(begin);
      emit(TokKind::Ident, begin, pos_ - begin, space);
    } else if (is_digit(c) || (c == '.' && is_digit(static_cast<unsigned char>(peek(1))))) {
      lex_number();
      emit(TokKind::Number, begin, pos_ - begin, space);
    } else if (c == '"') {
      size_t end = pos_ + 1;
      while (end < text_.size() && text_[end] != '"' && text_[end] != '\n') ++end;
      if (end >= text_.size() || text_[end] != '"') {
        error(begin, 1, "syntax", "missing closing '\"'");
        pos_ = end;
        return true;
      }
      pos_ = end + 1;
      emit(TokKind::String, begin, pos_ - begin, space);
    } else if (c >= 0x80) {
      uint32_t cp = 0;
      size_t n = utf8_length(text_, pos_, cp);
      if (n == 0) {
        // Bytes of a legacy 8-bit code page (Windows-1252, -1251) are fine in comments, which
        // are skipped unread; outside one, a statement never holds them.
        binary_error("input is not valid UTF-8 text (binary file?)");
        return false;
      }
      error(begin, n, "syntax", fmt::format("unexpected character U+{:04X}", cp));
      pos_ += n;
    } else if (c < 0x20 || c == 0x7F) {
      error(begin, 1, "syntax", fmt::format("unexpected control character 0x{:02X}", c));
      ++pos_;
    } else {
      lex_punct(c, space);
    }
    return true;
  }

  // "vs.1.1" / "ps.2.0": the D3D8 spelling of the version is one token.
  void extend_dot_version(size_t begin) {
    if (pos_ - begin != 2) return;
    char a = static_cast<char>(text_[begin] | 0x20), b = static_cast<char>(text_[begin + 1] | 0x20);
    if (!((a == 'v' || a == 'p') && b == 's')) return;
    size_t p = pos_;
    for (int part = 0; part < 2; ++part) {
      if (p >= text_.size() || text_[p] != '.') return;
      size_t digits = p + 1;
      while (digits < text_.size() && is_ident_char(static_cast<unsigned char>(text_[digits])))
        ++digits;
      if (digits == p + 1) return;
      p = digits;
    }
    pos_ = p;
  }

  void lex_number() {
    auto digits = [&] {
      while (pos_ < text_.size() && is_digit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    };
    digits();
    // "1.5", "1.", and "1.f" (C spelling) are numbers; "1.xyz" is not a thing in asm.
    bool dot_f =
        (peek(1) == 'f' || peek(1) == 'F') && !is_ident_char(static_cast<unsigned char>(peek(2)));
    if (peek(0) == '.' && (dot_f || !is_ident_start(static_cast<unsigned char>(peek(1))))) {
      ++pos_;
      digits();
    }
    if ((peek(0) == 'e' || peek(0) == 'E') &&
        (is_digit(static_cast<unsigned char>(peek(1))) ||
         ((peek(1) == '-' || peek(1) == '+') && is_digit(static_cast<unsigned char>(peek(2)))))) {
      pos_ += 2;
      digits();
    }
    // Suffixes (1.0f) and hex digits (0x1F) stay in the token; readers judge them.
    while (pos_ < text_.size() && is_ident_char(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }

  void lex_punct(unsigned char c, bool space) {
    static constexpr std::string_view two[] = {
        "&&", "||", "==", "!=", "<=", ">=", "<<", ">>", "##"};
    for (std::string_view op : two)
      if (c == static_cast<unsigned char>(op[0]) && peek(1) == op[1]) {
        emit(TokKind::Punct, pos_, 2, space);
        pos_ += 2;
        return;
      }
    emit(TokKind::Punct, pos_, 1, space);
    ++pos_;
  }

  uint32_t file_;
  std::string_view text_;
  ir::DiagnosticSink& diags_;
  std::vector<Token>* out_ = nullptr;
  size_t pos_ = 0;
  size_t line_start_ = 0;
  uint32_t line_ = 1;
  size_t errors_ = 0;
  bool error_on_line_ = false;
  bool stopped_ = false;
  bool started_ = false;
  bool finished_ = false;
  bool space_ = true;
  LexStatus status_ = LexStatus::Ok;
};

LineLexer::LineLexer(uint32_t file, std::string_view text, ir::DiagnosticSink& diags)
    : impl_(std::make_unique<Impl>(file, text, diags)) {}
LineLexer::~LineLexer() = default;
bool LineLexer::next_line(std::vector<Token>& out) {
  return impl_->next_line(out);
}
LexStatus LineLexer::status() const {
  return impl_->status();
}

LexStatus lex_text(uint32_t file, std::string_view text, ir::DiagnosticSink& diags,
                   std::vector<Token>& out) {
  LineLexer lexer(file, text, diags);
  while (lexer.next_line(out)) {
  }
  return lexer.status();
}

} // namespace tierlift::assembly
