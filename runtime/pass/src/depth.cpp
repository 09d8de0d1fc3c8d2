// D3DCMPFUNC's names (depth.h).
#include "tierlift/pass/depth.h"

#include <array>
#include <cctype>
#include <string>
#include <utility>

namespace tierlift::pass {
namespace {

constexpr std::array<std::pair<std::string_view, CompareFunc>, 8> kNames{{
    {"never", CompareFunc::Never},
    {"less", CompareFunc::Less},
    {"equal", CompareFunc::Equal},
    {"lessequal", CompareFunc::LessEqual},
    {"greater", CompareFunc::Greater},
    {"notequal", CompareFunc::NotEqual},
    {"greaterequal", CompareFunc::GreaterEqual},
    {"always", CompareFunc::Always},
}};

} // namespace

bool parse_compare_func(std::string_view word, CompareFunc& out) {
  std::string lower;
  for (char c : word) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string_view w = lower;
  if (w.starts_with("d3dcmp_")) w.remove_prefix(7);
  for (const auto& [name, func] : kNames)
    if (w == name) {
      out = func;
      return true;
    }
  return false;
}

std::string_view compare_func_name(CompareFunc func) {
  for (const auto& [name, f] : kNames)
    if (f == func) return name;
  return "?";
}

} // namespace tierlift::pass
