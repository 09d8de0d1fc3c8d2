// Comment blocks in text: "//!comment" followed by the block's words in hexadecimal, and
// "//!comment+" lines that add words to the block just before them (the printer writes eight
// words a line). The block goes into the program where it stands among the statements, so
// that the assembler writes its comment token at the same place of the stream.
#include <charconv>

#include <fmt/format.h>

#include "parser_impl.h"

namespace tierlift::assembly::detail {
namespace {

// "0x0000001c": one to eight hexadecimal digits after 0x, nothing else.
bool hex_word(std::string_view text, uint32_t& out) {
  if (text.size() < 3 || text.size() > 10 || text[0] != '0' || (text[1] != 'x' && text[1] != 'X'))
    return false;
  const char* first = text.data() + 2;
  const char* last = text.data() + text.size();
  auto [end, ec] = std::from_chars(first, last, out, 16);
  return ec == std::errc() && end == last;
}

} // namespace

bool Parser::comment_block() {
  const Token& mark = cur();
  advance();
  const bool continues = at_punct("+") && !cur().space_before;
  if (continues) advance();
  if (continues) {
    // Only a block that is the statement just before may grow: words cannot jump over code.
    if (prog_.comments.empty() || prog_.comments.back().seq + 1 != seq_)
      return fail(mark.loc, "comment-block",
                  "'//!comment+' adds words to a comment block, but the statement before it is "
                  "not one (start the block with '//!comment')");
  } else {
    ir::CommentBlock block;
    block.loc = mark.loc;
    block.seq = seq_++;
    prog_.comments.push_back(std::move(block));
  }
  std::vector<uint32_t>& words = prog_.comments.back().words;
  for (; !at_eol(); advance()) {
    uint32_t word = 0;
    if (cur().kind != TokKind::Number || !hex_word(cur().text, word))
      return fail(cur().loc, "comment-block",
                  fmt::format("expected a 32-bit word in hexadecimal (0x0000001c) in a comment "
                              "block, found {}",
                              describe(cur())));
    words.push_back(word);
  }
  return true;
}

} // namespace tierlift::assembly::detail
