#include "tierlift/ir/source.h"

namespace tierlift::ir {

std::string SourceManager::line_text(uint32_t file, uint32_t line) const {
  if (file >= files.size() || line == 0) return {};
  const std::string& t = files[file].text;
  size_t pos = 0;
  for (uint32_t l = 1; l < line; ++l) {
    pos = t.find('\n', pos);
    if (pos == std::string::npos) return {};
    ++pos;
  }
  size_t end = t.find('\n', pos);
  std::string s = t.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
  if (!s.empty() && s.back() == '\r') s.pop_back();
  return s;
}

} // namespace tierlift::ir
