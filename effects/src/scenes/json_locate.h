// Where the values of a JSON text are, by JSON pointer (RFC 6901). nlohmann-json 3.11 keeps
// no positions for values, but scene diagnostics need a line, a column and a caret for the
// field at fault; this walks the text once more and records every value's byte span.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tierlift::effects {

struct TextSpan {
  size_t offset = 0, length = 0; // bytes of the text
};

struct JsonPlace {
  TextSpan key;   // the member's key with its quotes (length 0 for array elements, the root)
  TextSpan value; // the whole value: `9`, `"dx9"`, `{ … }`
};

struct JsonLocations {
  std::map<std::string, JsonPlace> at; // "" = the root, "/glow/downsample", "/size/0", …
  // Keys met a second time in the same object (nlohmann keeps the last value): pointer and
  // the later key.
  std::vector<std::pair<std::string, TextSpan>> duplicate_keys;
  std::optional<TextSpan> number_overflow; // the first number beyond the range of a double
};

// For text nlohmann accepted (or rejected only for a number overflow). Never reads out of
// bounds on other text: it stops where the text stops making sense.
JsonLocations locate_json(std::string_view text);

// Offset of the first '[' or '{' nested deeper than `limit` (outside strings), if any:
// checked before parsing so that no recursion runs deep.
std::optional<size_t> nesting_beyond(std::string_view text, int limit);

struct LineCol {
  uint32_t line = 1, col = 1; // 1-based; col counts bytes, like the listing lexer
};
LineCol line_col(std::string_view text, size_t offset);

// A key as a JSON pointer token: '~' → "~0", '/' → "~1".
std::string pointer_token(std::string_view key);

} // namespace tierlift::effects
