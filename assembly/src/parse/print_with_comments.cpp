// The canonical text with the listing's own comments and paragraphs kept: `tierlift fmt`
// must not delete what a person wrote beside the code. Statements come from the IR (as in
// print_program); the comments and blank lines come from the source text, by line.
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/assembly/preprocessor.h"
#include "tierlift/assembly/printer.h"

namespace tierlift::assembly {
namespace {

// One source line split into what the parser reads and what it skips.
struct LineTrivia {
  bool code = false;   // anything outside comments (a statement or a directive)
  std::string comment; // the comments of the line, as written
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

// "//!comment" at text[i], not followed by a letter (as the lexer reads it).
bool comment_block_at(std::string_view text, size_t i) {
  if (!text.substr(i).starts_with(kCommentBlockMark)) return false;
  size_t end = i + kCommentBlockMark.size();
  if (end >= text.size()) return true;
  const char c = text[end];
  return !((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_');
}

// The comment syntax of the lexer: ';' and '//' to the end of the line, '/* */' anywhere
// (across lines too).
std::vector<LineTrivia> scan(std::string_view text) {
  std::vector<LineTrivia> lines(1);
  bool in_block = false;
  std::string piece; // the comment being collected on this line
  auto flush_piece = [&] {
    std::string_view t = trim(piece);
    if (!t.empty()) {
      if (!lines.back().comment.empty()) lines.back().comment += ' ';
      lines.back().comment += t;
    }
    piece.clear();
  };
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '\n') {
      flush_piece();
      lines.emplace_back();
      continue;
    }
    if (in_block) {
      piece += c;
      if (c == '*' && next == '/') {
        piece += '/';
        ++i;
        in_block = false;
        flush_piece();
      }
      continue;
    }
    if (comment_block_at(text, i)) {
      // A comment block's line: the IR holds its words and prints them as a statement.
      lines.back().code = true;
      size_t end = text.find('\n', i);
      i = (end == std::string_view::npos ? text.size() : end) - 1;
      continue;
    }
    if (c == ';' || (c == '/' && next == '/')) {
      size_t end = text.find('\n', i);
      if (end == std::string_view::npos) end = text.size();
      piece.append(text.substr(i, end - i));
      i = end - 1;
      continue;
    }
    if (c == '/' && next == '*') {
      in_block = true;
      piece += "/*";
      ++i;
      continue;
    }
    if (c != ' ' && c != '\t' && c != '\r') lines.back().code = true;
  }
  flush_piece();
  return lines;
}

// The line of a statement in the main file, or 0 (from an #include, or no position).
uint32_t line_in(const ir::SourceLoc& loc, uint32_t file) {
  return loc.file == file ? loc.line : 0;
}

} // namespace

std::string print_program_with_comments(const ir::Program& p, std::string_view source,
                                        uint32_t file) {
  const std::vector<LineTrivia> lines = scan(source);
  std::string out;
  bool pending_blank = false; // a blank line is printed only before more text
  auto emit = [&](const std::string& text) {
    if (pending_blank && !out.empty()) out += '\n';
    pending_blank = false;
    out += text;
    out += '\n';
  };
  // Comment-only and blank lines in (from, to): blank runs become one blank line.
  auto between = [&](uint32_t from, uint32_t to) {
    for (uint32_t l = from + 1; l < to && l <= lines.size(); ++l) {
      const LineTrivia& t = lines[l - 1];
      if (t.code) continue; // a directive: the statements it made are printed expanded
      if (t.comment.empty())
        pending_blank = true;
      else
        emit(t.comment);
    }
  };
  auto with_comment = [&](std::string text, uint32_t line) {
    if (line >= 1 && line <= lines.size() && !lines[line - 1].comment.empty())
      text += "  " + lines[line - 1].comment;
    return text;
  };

  uint32_t at = 0; // the last source line printed
  const uint32_t version_line = line_in(p.version_loc, file);
  if (version_line) between(0, version_line);
  emit(with_comment(std::string(ir::profile_name(p.profile)), version_line));
  at = version_line;
  for (const auto& st : p.statements()) {
    std::string text;
    ir::SourceLoc loc;
    switch (st.kind) {
    case ir::Program::Statement::Kind::Decl:
      text = print_declaration(p.decls[st.index], p.profile);
      loc = p.decls[st.index].loc;
      break;
    case ir::Program::Statement::Kind::Def:
      text = print_definition(p.defs[st.index]);
      loc = p.defs[st.index].loc;
      break;
    case ir::Program::Statement::Kind::Code:
      text = print_instruction(p.code[st.index], p.profile);
      loc = p.code[st.index].loc;
      break;
    case ir::Program::Statement::Kind::Comment:
      text = print_comment_block(p.comments[st.index]);
      loc = p.comments[st.index].loc;
      break;
    }
    const uint32_t line = line_in(loc, file);
    if (line > at) { // the first statement of a later line carries that line's comments
      between(at, line);
      emit(with_comment(std::move(text), line));
      at = line;
    } else {
      emit(text);
    }
  }
  between(at, static_cast<uint32_t>(lines.size()) + 1);
  return out;
}

} // namespace tierlift::assembly
