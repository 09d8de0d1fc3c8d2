// The D3DX assembler's C-style preprocessor and the token stream it hands to the parser.
//
// The lexer turns each file into tokens (comments dropped, positions kept); the
// preprocessor runs directives line by line and expands macros. Every token keeps the
// position of the text it came from; a token produced by a macro expansion carries the
// position of the macro use, so diagnostics always point at something the user wrote.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/assembly/parser.h"
#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/source.h"

namespace tierlift::assembly {

enum class TokKind : uint8_t {
  Ident,   // [A-Za-z_][A-Za-z0-9_]*, plus the dot version spelling "ps.1.4" as one token
  Number,  // 1  1.0  .5  1e-3  1.0f  0x1F (validity is judged by whoever reads it)
  String,  // "file.inc" (the quotes are part of text)
  Punct,   // , . [ ] + - ! ( ) # and the two-character operators of #if expressions
  Newline, // end of a source line (statements and directives are line based)
  End,     // end of the whole stream
};

// A line comment that starts with this mark holds the words of a token-stream comment block
// (ir::CommentBlock): the lexer hands it out as one Punct token, the rest of the line as
// ordinary tokens. Other assemblers read it as the comment it looks like.
inline constexpr std::string_view kCommentBlockMark = "//!comment";

struct Token {
  TokKind kind = TokKind::End;
  bool space_before = false; // white space or a comment separates it from the previous token
  std::string_view text;     // points into TokenStream::storage
  ir::SourceLoc loc;
};

struct TokenStream {
  std::vector<Token> tokens; // always ends with one End token
  // Stable copies of every text the tokens point into (files, -D values). unique_ptr keeps
  // each buffer at one address while the vector grows.
  std::vector<std::unique_ptr<std::string>> storage;
  // A file turned out to be binary: its one error has been reported and nothing more
  // should be said about the input.
  bool binary = false;
};

enum class LexStatus { Ok, Stopped, Binary };

// Lexes one line at a time, so that a large file never exists twice as tokens.
class LineLexer {
public:
  LineLexer(uint32_t file, std::string_view text, ir::DiagnosticSink& diags);
  ~LineLexer();
  LineLexer(const LineLexer&) = delete;
  LineLexer& operator=(const LineLexer&) = delete;
  // Appends the next line's tokens, ending with one Newline token. False when no line is
  // left (end of text, or binary input: see status()).
  bool next_line(std::vector<Token>& out);
  LexStatus status() const;

private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

// Lexes one file's text. Appends tokens (with Newline tokens, without End) to `out`.
// Returns Stopped after an unclosed block comment or too many errors, Binary for binary input.
LexStatus lex_text(uint32_t file, std::string_view text, ir::DiagnosticSink& diags,
                   std::vector<Token>& out);

// Runs the preprocessor over sm.files[file] (and whatever it #includes, which is added to
// sm). Errors go to diags; the stream is still returned so the parser can report more.
TokenStream preprocess(uint32_t file, ir::SourceManager& sm, ir::DiagnosticSink& diags,
                       const ParseOptions& options);

// The files #include opened while `sm` was filled (directly or through another include), as
// the paths they were opened by, each once, in the order first opened. They are inputs of
// the command as much as the listing: no output may replace one (io::refuse_if_input).
std::vector<std::string> included_files(const ir::SourceManager& sm);

// What a listing's text needs the preprocessor for, if anything: the position of its first
// directive (a line starting with '#', taken or skipped) or of its first use of a macro
// given as `options.defines` (-D). `fmt` prints the IR, in which directives and macros no
// longer exist, so it refuses such a listing rather than lose them.
struct PreprocessorUse {
  ir::SourceLoc loc;
  std::string what; // "#include", "#define", "#ifdef", …, or "macro NAME"
};
std::optional<PreprocessorUse> first_preprocessor_use(uint32_t file, const ir::SourceManager& sm,
                                                      const ParseOptions& options);

} // namespace tierlift::assembly
