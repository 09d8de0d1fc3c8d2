#include "named_constants.h"

#include <cctype>

#include <fmt/format.h>

namespace tierlift::cli {
namespace {

// cN, iN, bN: a register, left to the run options' own parser.
bool is_register_name(std::string_view name) {
  if (name.size() < 2 || (name[0] != 'c' && name[0] != 'i' && name[0] != 'b')) return false;
  for (char ch : name.substr(1))
    if (!std::isdigit(static_cast<unsigned char>(ch))) return false;
  return true;
}

std::vector<std::string> split_values(std::string_view value) {
  std::vector<std::string> out;
  size_t start = 0;
  for (;;) {
    size_t comma = value.find(',', start);
    out.emplace_back(value.substr(start, comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

// The register settings `value` makes of `c`, or why it does not fit.
ir::Result<std::vector<std::string>> expand(std::string_view prefix, const as::NamedConstant& c,
                                            std::string_view value) {
  auto fail = [&](std::string why) { return ir::fail(c.name, "usage", std::move(why)); };
  std::vector<std::string> values = split_values(value);
  std::vector<std::string> out;
  if (c.set == as::ConstantSet::Bool) {
    if (values.size() != 1)
      return fail(fmt::format("'{}' ({}) takes one value, true or false", c.name, c.registers()));
    out.push_back(fmt::format("{}b{}={}", prefix, c.index, value));
    return out;
  }
  if (c.set == as::ConstantSet::Sampler)
    return fail(
        fmt::format("'{}' is a sampler ({}); bind it with --texture", c.name, c.registers()));
  if (values.size() % 4 != 0 || values.size() > 4 * size_t{c.count})
    return fail(fmt::format("'{}' ({}, {}) takes 4 numbers per register, at most {}; got {}",
                            c.name, c.registers(), c.type.empty() ? "?" : c.type, 4 * c.count,
                            values.size()));
  const char* file = c.set == as::ConstantSet::Int4 ? "i" : "c";
  for (size_t r = 0; r < values.size() / 4; ++r)
    out.push_back(fmt::format("{}{}{}={},{},{},{}", prefix, file, c.index + r, values[4 * r],
                              values[4 * r + 1], values[4 * r + 2], values[4 * r + 3]));
  return out;
}

} // namespace

ir::Result<std::vector<std::string>>
resolve_named_constants(const std::vector<std::string>& settings, const as::ConstantTable* vs,
                        const as::ConstantTable* ps) {
  std::vector<std::string> out;
  for (const std::string& s : settings) {
    std::string_view body = s;
    bool want_vs = true, want_ps = true;
    if (body.starts_with("vs:"))
      want_ps = false, body.remove_prefix(3);
    else if (body.starts_with("ps:"))
      want_vs = false, body.remove_prefix(3);
    size_t eq = body.find('=');
    std::string_view name = body.substr(0, eq);
    if (eq == std::string_view::npos || is_register_name(name)) {
      out.push_back(s);
      continue;
    }
    bool found = false;
    for (auto [stage, table, wanted] : {std::tuple{"vs:", vs, want_vs}, {"ps:", ps, want_ps}}) {
      const as::NamedConstant* c = wanted && table ? table->find(name) : nullptr;
      if (!c) continue;
      ir::Result<std::vector<std::string>> regs = expand(stage, *c, body.substr(eq + 1));
      if (!regs) return ir::fail(s, "usage", fmt::format("--const '{}': {}", s, regs.message()));
      out.insert(out.end(), regs->begin(), regs->end());
      found = true;
    }
    if (!found)
      return ir::fail(s, "usage",
                      fmt::format("--const '{}': '{}' is neither a register (cN, iN, bN) nor a "
                                  "constant named in the listings' constant tables (CTAB){}",
                                  s, name, vs || ps ? "" : "; these listings carry none"));
  }
  return out;
}

} // namespace tierlift::cli
