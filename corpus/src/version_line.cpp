#include "version_line.h"

#include <cctype>

namespace tierlift::corpus {

std::optional<char> version_line_major(std::string_view text) {
  auto lower = [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  };
  auto digit = [&](size_t k) { return text[k] >= '0' && text[k] <= '9'; };
  auto sep = [&](size_t k) { return text[k] == '.' || text[k] == '_'; };
  for (size_t i = 0; i < text.size();) {
    size_t at = i;
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
    if (at + 6 <= text.size()) {
      const char a = lower(text[at]), b = lower(text[at + 1]), last = lower(text[at + 5]);
      if ((a == 'v' || a == 'p') && b == 's' && sep(at + 2) && digit(at + 3) && sep(at + 4) &&
          (digit(at + 5) || last == 'x' || last == 's' || last == 'w'))
        return text[at + 3];
    }
    const size_t newline = text.find('\n', i);
    if (newline == std::string_view::npos) break;
    i = newline + 1;
  }
  return std::nullopt;
}

} // namespace tierlift::corpus
