// Renaming of shader model 3's semantic-linked registers onto the 2.0 interface (see
// sm3_interface.h for why the backends want it).
#include "tierlift/ir/sm3_interface.h"

#include <map>

#include <fmt/format.h>

namespace tierlift::ir {
namespace {

// The file a 3.0 program declares its linked registers in: o# (vs_3_0), v# (ps_3_0).
std::optional<RegFile> linked_file(Profile p) {
  if (p == Profile::vs_3_0) return RegFile::Output;
  if (p == Profile::ps_3_0) return RegFile::Input;
  return std::nullopt;
}

std::string usage_text(DeclUsage u, uint8_t index) {
  static constexpr const char* kNames[] = {
      "position", "blendweight", "blendindices", "normal", "psize", "texcoord", "tangent",
      "binormal", "tessfactor",  "positiont",    "color",  "fog",   "depth",    "sample"};
  const auto i = static_cast<size_t>(u);
  return fmt::format("{}{}", i < std::size(kNames) ? kNames[i] : "?", index);
}

using Renames = std::map<uint32_t, std::pair<RegFile, uint32_t>>;

Renames renames(const Program& program, RegFile file) {
  Renames out;
  for (const Declaration& d : program.decls)
    if (d.reg.file == file)
      if (auto r = semantic_register(program.stage(), d.usage, d.usage_index))
        out.emplace(d.reg.index, *r);
  return out;
}

} // namespace

std::optional<std::pair<RegFile, uint32_t>> semantic_register(ShaderStage stage, DeclUsage usage,
                                                              uint8_t usage_index) {
  const bool vertex = stage == ShaderStage::Vertex;
  switch (usage) {
  case DeclUsage::Position:
    if (vertex && usage_index == 0) return std::pair{RegFile::RastOut, kRastPos};
    break;
  case DeclUsage::PSize:
    if (vertex && usage_index == 0) return std::pair{RegFile::RastOut, kRastPts};
    break;
  case DeclUsage::Fog:
    if (vertex && usage_index == 0) return std::pair{RegFile::RastOut, kRastFog};
    break;
  case DeclUsage::Color:
    if (usage_index < 2)
      return std::pair{vertex ? RegFile::AttrOut : RegFile::Input, uint32_t{usage_index}};
    break;
  case DeclUsage::TexCoord:
    if (usage_index < 8)
      return std::pair{vertex ? RegFile::TexCrdOut : RegFile::Texture, uint32_t{usage_index}};
    break;
  default: break;
  }
  return std::nullopt;
}

void check_semantic_interface(const Program& program, std::string_view backend,
                              DiagnosticSink& sink) {
  const std::optional<RegFile> file = linked_file(program.profile);
  if (!file) return;
  std::map<uint32_t, const Declaration*> seen;
  for (const Declaration& d : program.decls) {
    if (d.reg.file != *file) continue;
    if (!semantic_register(program.stage(), d.usage, d.usage_index))
      sink.error(d.loc, "not-supported",
                 fmt::format("not supported yet by {}: the semantic {} ({} links position0, "
                             "psize0, fog0, color0-1 and texcoord0-7)",
                             backend, usage_text(d.usage, d.usage_index), backend));
    if (!seen.emplace(d.reg.index, &d).second)
      sink.error(d.loc, "not-supported",
                 fmt::format("not supported yet by {}: two semantics in {} (one semantic per "
                             "register)",
                             backend, register_name(d.reg.file, d.reg.index)));
  }
}

Program link_by_semantic(const Program& program) {
  const std::optional<RegFile> file = linked_file(program.profile);
  if (!file) return program;
  const Renames map = renames(program, *file);
  Program out = program;
  auto rename = [&](RegFile& f, uint32_t& index) {
    if (f != *file) return;
    if (auto it = map.find(index); it != map.end()) std::tie(f, index) = it->second;
  };
  for (Declaration& d : out.decls) rename(d.reg.file, d.reg.index);
  for (Instruction& ins : out.code) {
    if (ins.dst) rename(ins.dst->file, ins.dst->index);
    for (SrcOperand& s : ins.src) rename(s.file, s.index);
  }
  return out;
}

} // namespace tierlift::ir
