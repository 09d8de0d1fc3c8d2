#include "tierlift/ir/ps1x_range.h"

#include <cctype>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

namespace tierlift::ir {
namespace {

bool iequal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

} // namespace

std::string ps1x_choices() {
  std::string out;
  for (const Ps1xPreset& p : kPs1xPresets) {
    const std::string value =
        p.max_value == FLT_MAX ? std::string("FLT_MAX") : fmt::format("{}", p.max_value);
    const bool is_default = p.name == kDefaultPs1xPreset;
    out += fmt::format("{} ({}{}), ", p.name, value, is_default ? ", the default" : "");
  }
  return out + "or a number >= 1";
}

Result<float> parse_ps1x_max(std::string_view text) {
  for (const Ps1xPreset& p : kPs1xPresets)
    if (iequal(text, p.name)) return p.max_value;
  auto fail = [&](std::string why) -> Result<float> {
    return ir::fail("ps1x-max", "value",
                    fmt::format("'{}': {}; expected {}", text, why, ps1x_choices()));
  };
  if (text.empty()) return fail("empty");
  // strtof on a NUL-terminated copy: std::from_chars for float is missing on older libstdc++.
  std::string copy(text);
  char* end = nullptr;
  errno = 0;
  float v = std::strtof(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size()) return fail("not a preset or a number");
  if (!std::isfinite(v) || errno == ERANGE) return fail("not a finite number");
  if (!(v >= 1.0f)) return fail("below 1, the least any ps_1_x part reports");
  return v;
}

std::string ps1x_max_label(float value) {
  for (const Ps1xPreset& p : kPs1xPresets)
    if (p.max_value == value) return std::string(p.name);
  return fmt::format("{}", value);
}

} // namespace tierlift::ir
