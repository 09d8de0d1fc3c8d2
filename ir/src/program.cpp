#include "tierlift/ir/program.h"

#include <algorithm>

#include <fmt/format.h>

namespace tierlift::ir {

std::vector<Program::Statement> Program::statements() const {
  std::vector<Statement> out;
  out.reserve(decls.size() + defs.size() + code.size() + comments.size());
  for (size_t i = 0; i < decls.size(); ++i) out.push_back({Statement::Kind::Decl, i});
  for (size_t i = 0; i < defs.size(); ++i) out.push_back({Statement::Kind::Def, i});
  for (size_t i = 0; i < code.size(); ++i) out.push_back({Statement::Kind::Code, i});
  for (size_t i = 0; i < comments.size(); ++i) out.push_back({Statement::Kind::Comment, i});
  auto seq = [this](const Statement& s) {
    switch (s.kind) {
    case Statement::Kind::Decl: return decls[s.index].seq;
    case Statement::Kind::Def: return defs[s.index].seq;
    case Statement::Kind::Code: return code[s.index].seq;
    case Statement::Kind::Comment: return comments[s.index].seq;
    }
    return uint32_t{0};
  };
  std::stable_sort(out.begin(), out.end(),
                   [&](const Statement& a, const Statement& b) { return seq(a) < seq(b); });
  return out;
}

namespace {

bool same(const InstrMods& a, const InstrMods& b) {
  return a.sat == b.sat && a.pp == b.pp && a.centroid == b.centroid && a.shift == b.shift;
}
bool same(const std::optional<RelAddr>& a, const std::optional<RelAddr>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (a->file == b->file && a->component == b->component &&
                a->token_swizzle() == b->token_swizzle());
}
bool same(const DstOperand& a, const DstOperand& b) {
  return a.file == b.file && a.index == b.index && a.mask == b.mask && same(a.rel, b.rel);
}
bool same(const SrcOperand& a, const SrcOperand& b) {
  if (a.file != b.file || a.index != b.index || a.swizzle != b.swizzle || a.mod != b.mod)
    return false;
  return same(a.rel, b.rel);
}

std::string where(const SourceLoc& loc) {
  return loc.valid() ? fmt::format(" (line {})", loc.line) : std::string();
}

} // namespace

std::string ir_difference(const Program& a, const Program& b) {
  if (a.profile != b.profile) return "profiles differ";
  if (a.decls.size() != b.decls.size())
    return fmt::format("{} vs {} declarations", a.decls.size(), b.decls.size());
  if (a.defs.size() != b.defs.size())
    return fmt::format("{} vs {} constant definitions", a.defs.size(), b.defs.size());
  if (a.code.size() != b.code.size())
    return fmt::format("{} vs {} instructions", a.code.size(), b.code.size());
  // Order of statements (decl/def/code interleaving) must match too; comment blocks are
  // not part of the shader.
  auto shader_only = [](std::vector<Program::Statement> all) {
    std::erase_if(all, [](const Program::Statement& s) {
      return s.kind == Program::Statement::Kind::Comment;
    });
    return all;
  };
  auto sa = shader_only(a.statements()), sb = shader_only(b.statements());
  for (size_t i = 0; i < sa.size(); ++i)
    if (sa[i].kind != sb[i].kind || sa[i].index != sb[i].index)
      return fmt::format("statement order differs at statement {}", i + 1);
  for (size_t i = 0; i < a.decls.size(); ++i) {
    const auto &x = a.decls[i], &y = b.decls[i];
    if (!same(x.reg, y.reg) || x.usage != y.usage || x.usage_index != y.usage_index ||
        x.sampler_type != y.sampler_type || !same(x.mods, y.mods))
      return fmt::format("declaration {} differs{}", i + 1, where(x.loc));
  }
  for (size_t i = 0; i < a.defs.size(); ++i) {
    const auto &x = a.defs[i], &y = b.defs[i];
    if (x.file != y.file || x.index != y.index || x.raw != y.raw)
      return fmt::format("definition {} differs{}", i + 1, where(x.loc));
  }
  for (size_t i = 0; i < a.code.size(); ++i) {
    const auto &x = a.code[i], &y = b.code[i];
    if (x.op != y.op) return fmt::format("instruction {} opcode differs{}", i + 1, where(x.loc));
    if (!same(x.mods, y.mods) || x.coissue != y.coissue)
      return fmt::format("instruction {} modifiers differ{}", i + 1, where(x.loc));
    if (x.pred.has_value() != y.pred.has_value() || (x.pred && !same(*x.pred, *y.pred)))
      return fmt::format("instruction {} predicate differs{}", i + 1, where(x.loc));
    if (x.dst.has_value() != y.dst.has_value() || (x.dst && !same(*x.dst, *y.dst)))
      return fmt::format("instruction {} destination differs{}", i + 1, where(x.loc));
    if (x.src.size() != y.src.size())
      return fmt::format("instruction {} source count differs{}", i + 1, where(x.loc));
    for (size_t k = 0; k < x.src.size(); ++k)
      if (!same(x.src[k], y.src[k]))
        return fmt::format("instruction {} source {} differs{}", i + 1, k + 1, where(x.loc));
  }
  return {};
}

bool same_ir(const Program& a, const Program& b) {
  return ir_difference(a, b).empty();
}

} // namespace tierlift::ir
