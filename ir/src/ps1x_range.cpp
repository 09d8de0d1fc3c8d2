#include "tierlift/ir/ps1x_range.h"

#include <array>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

namespace tierlift::ir {
namespace {

// Order matters for ps1x_max_label: the first preset with a value names it.
constexpr std::array<Ps1xPreset, 4> kPresets{{
    {"d3d9", FLT_MAX,
     "a D3D9-class driver: float pipelines, the range reported as FLT_MAX (the default)"},
    {"geforce3", 1.0f, "the first ps_1_1 parts (GeForce3/4 Ti): registers clamp to [-1, 1]"},
    {"radeon8500", 8.0f, "ps_1_4 parts (Radeon 8500): [-8, 8], the least ps_1_4 allows"},
    {"max", FLT_MAX, "the largest finite float: no clamp short of overflow"},
}};

bool iequal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

} // namespace

std::span<const Ps1xPreset> ps1x_presets() {
  return kPresets;
}

float default_ps1x_max() {
  return FLT_MAX;
}

Result<float> parse_ps1x_max(std::string_view text) {
  for (const Ps1xPreset& p : kPresets)
    if (iequal(text, p.name)) return p.max_value;
  auto fail = [&](std::string why) -> Result<float> {
    return ir::fail("ps1x-max", "value",
                    fmt::format("'{}': {}; expected geforce3 (1), radeon8500 (8), d3d9, max or a "
                                "number >= 1",
                                text, why));
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
  for (const Ps1xPreset& p : kPresets)
    if (p.max_value == value) return std::string(p.name);
  return fmt::format("{}", value);
}

} // namespace tierlift::ir
