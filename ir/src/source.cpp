#include "tierlift/ir/source.h"

namespace tierlift::ir {

namespace {
// The end of the line starting at `pos`: the next '\n', or a '\r' not followed by '\n'
// (CR-only line endings, as the lexer counts them); npos at the end of the text.
size_t line_end(const std::string& t, size_t pos) {
  for (size_t i = t.find_first_of("\r\n", pos); i != std::string::npos;
       i = t.find_first_of("\r\n", i + 1))
    if (t[i] == '\n' || i + 1 == t.size() || t[i + 1] != '\n') return i;
  return std::string::npos;
}
} // namespace

std::string SourceManager::line_text(uint32_t file, uint32_t line) const {
  if (file >= files.size() || line == 0) return {};
  const std::string& t = files[file].text;
  size_t pos = 0;
  for (uint32_t l = 1; l < line; ++l) {
    pos = line_end(t, pos);
    if (pos == std::string::npos) return {};
    ++pos;
  }
  size_t end = line_end(t, pos);
  std::string s = t.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
  if (!s.empty() && s.back() == '\r') s.pop_back();
  return s;
}

} // namespace tierlift::ir
