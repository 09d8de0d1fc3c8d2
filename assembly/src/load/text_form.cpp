// What a text file that is no token stream is (text_form.h).
#include "tierlift/assembly/text_form.h"

#include <cctype>

#include <fmt/format.h>

#include "tierlift/assembly/bytecode.h"

namespace tierlift::assembly {
namespace {

// The first character that is neither white space nor in a // or /* */ comment.
size_t first_content(std::string_view b) {
  size_t i = 0;
  while (i < b.size()) {
    if (std::isspace(static_cast<unsigned char>(b[i]))) {
      ++i;
    } else if (b.substr(i, 2) == "//") {
      const size_t nl = b.find('\n', i);
      i = nl == std::string_view::npos ? b.size() : nl + 1;
    } else if (b.substr(i, 2) == "/*") {
      const size_t end = b.find("*/", i + 2);
      i = end == std::string_view::npos ? b.size() : end + 2;
    } else {
      break;
    }
  }
  return i;
}

} // namespace

std::string describe_text_form(std::string_view bytes, ir::DiagnosticSink& why, uint32_t file) {
  const size_t first = first_content(bytes);
  if (first == bytes.size())
    return bytes.empty() ? "an empty file" : "a file of nothing but white space and comments";
  // Assembly starts with a version (vs_1_1, ps.2.0), a directive or a comment; a C array
  // has braces or starts with a number (a bare list of DWORDs).
  const bool c_like = bytes.find('{') != std::string_view::npos ||
                      std::isdigit(static_cast<unsigned char>(bytes[first]));
  if (!c_like) return {};
  ir::DiagnosticSink scratch;
  auto tokens = read_token_file(std::string(bytes), scratch, file);
  for (const ir::Diagnostic& d : scratch.all()) why.add(d);
  if (!tokens || scratch.has_errors()) return "a C array that does not read";
  if (tokens->empty()) return "a C array with no values";
  return fmt::format("a C array whose first value 0x{:08X} is not a version token "
                     "(0xFFFE0101 .. 0xFFFF0200)",
                     tokens->front());
}

} // namespace tierlift::assembly
