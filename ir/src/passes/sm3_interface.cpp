// Renaming of shader model 3's semantic-linked registers onto the 2.0 interface (see
// sm3_interface.h for why the backends want it).
#include "tierlift/ir/sm3_interface.h"

#include <algorithm>
#include <bit>
#include <map>
#include <vector>

#include <fmt/format.h>

namespace tierlift::ir {
namespace {

constexpr int kSlots = 8; // texture-coordinate slots of the 2.0 interface: oT0-7 / t0-7

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
using Semantic = std::pair<DeclUsage, uint8_t>;

// A semantic the 2.0 interface has no register for in either stage (normal, tangent,
// binormal, blendweight, texcoord8, color2, fog0, ...): carried in a free texture-coordinate
// slot. fog0 is one: shader model 3 makes it a vector like any other (a vs_3_0 may write
// o1.xy as fog, unclamped), not the scalar oFog. position0 and psize0 have a vertex register
// but no pixel one, so a pixel program that reads them stays refused rather than taking a
// slot the vertex stage never fills.
bool is_extra(DeclUsage usage, uint8_t usage_index) {
  return !semantic_register(ShaderStage::Vertex, usage, usage_index);
}

struct Placement {
  std::map<Semantic, uint32_t> slot; // extra semantic -> texture-coordinate slot
  std::vector<const Declaration*> unplaced;
};

// The extra semantics of `file`, in (usage, index) order, take the slots t7, t6, ... that no
// texcoordN declaration of the same program names. The order depends on the set of
// semantics only (not on register numbers or declaration order), so a vertex and a pixel
// program that carry the same extra semantics and texcoords place them alike.
Placement place_extras(const Program& program, RegFile file) {
  std::map<Semantic, const Declaration*> extras;
  uint32_t taken = 0; // bit n: texcoordN is declared
  for (const Declaration& d : program.decls) {
    if (d.reg.file != file) continue;
    if (d.usage == DeclUsage::TexCoord && d.usage_index < kSlots) taken |= 1u << d.usage_index;
    if (is_extra(d.usage, d.usage_index)) extras.emplace(Semantic{d.usage, d.usage_index}, &d);
  }
  Placement out;
  int next = kSlots - 1;
  for (const auto& [semantic, decl] : extras) {
    while (next >= 0 && (taken & (1u << next))) --next;
    if (next < 0) {
      out.unplaced.push_back(decl);
      continue;
    }
    out.slot.emplace(semantic, static_cast<uint32_t>(next--));
  }
  return out;
}

Renames renames(const Program& program, RegFile file) {
  const Placement placed = place_extras(program, file);
  const RegFile slot_file =
      program.stage() == ShaderStage::Vertex ? RegFile::TexCrdOut : RegFile::Texture;
  Renames out;
  for (const Declaration& d : program.decls) {
    if (d.reg.file != file) continue;
    if (auto r = semantic_register(program.stage(), d.usage, d.usage_index))
      out.emplace(d.reg.index, *r);
    else if (auto it = placed.slot.find({d.usage, d.usage_index}); it != placed.slot.end())
      out.emplace(d.reg.index, std::pair{slot_file, it->second});
  }
  return out;
}

// Slot -> the semantic that fills it, for one stage as it runs: a 3.0 program by its
// declarations, an earlier one by the oT#/t# registers its code names (texcoordN at N).
std::map<uint32_t, Semantic> slot_semantics(const Program& program) {
  std::map<uint32_t, Semantic> out;
  const std::optional<RegFile> file = linked_file(program.profile);
  if (file) {
    const Placement placed = place_extras(program, *file);
    for (const auto& [semantic, slot] : placed.slot) out.emplace(slot, semantic);
    for (const Declaration& d : program.decls)
      if (d.reg.file == *file && d.usage == DeclUsage::TexCoord && d.usage_index < kSlots)
        out.emplace(d.usage_index, Semantic{DeclUsage::TexCoord, d.usage_index});
    return out;
  }
  const RegFile slot_file =
      program.stage() == ShaderStage::Vertex ? RegFile::TexCrdOut : RegFile::Texture;
  auto add = [&](RegFile f, uint32_t index) {
    if (f == slot_file && index < kSlots)
      out.emplace(index, Semantic{DeclUsage::TexCoord, static_cast<uint8_t>(index)});
  };
  for (const Declaration& d : program.decls) add(d.reg.file, d.reg.index);
  for (const Instruction& ins : program.code) {
    if (ins.dst) add(ins.dst->file, ins.dst->index);
    for (const SrcOperand& src : ins.src) add(src.file, src.index);
  }
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
    if (!semantic_register(program.stage(), d.usage, d.usage_index) &&
        !is_extra(d.usage, d.usage_index))
      sink.error(d.loc, "not-supported",
                 fmt::format("not supported yet by {}: the semantic {} in a pixel program (it "
                             "is a vertex-stage output only)",
                             backend, usage_text(d.usage, d.usage_index)));
    if (!seen.emplace(d.reg.index, &d).second)
      sink.error(d.loc, "not-supported",
                 fmt::format("not supported yet by {}: two semantics in {} (one semantic per "
                             "register)",
                             backend, register_name(d.reg.file, d.reg.index)));
  }
  for (const Declaration* d : place_extras(program, *file).unplaced)
    sink.error(d->loc, "not-supported",
               fmt::format("not supported yet by {}: the semantic {} (semantics beyond position0, "
                           "psize0, color0-1 and texcoord0-7 ride in the texcoord slots the "
                           "program leaves free, and none is left)",
                           backend, usage_text(d->usage, d->usage_index)));
}

Status check_semantic_pair(const Program& vertex, const Program& pixel) {
  if (!linked_file(vertex.profile) && !linked_file(pixel.profile)) return ok_status();
  const std::map<uint32_t, Semantic> vs = slot_semantics(vertex);
  const std::map<uint32_t, Semantic> ps = slot_semantics(pixel);
  for (const auto& entry : ps) {
    // Named copies, not structured bindings: a lambda cannot capture those before C++20's
    // P1091 fix, which clang 15 (the fuzz build's compiler) does not have.
    const uint32_t slot = entry.first;
    const Semantic semantic = entry.second;
    const auto there = vs.find(slot);
    const auto elsewhere = std::find_if(vs.begin(), vs.end(), [&](const auto& e) {
      return e.second == semantic && e.first != slot;
    });
    if ((there == vs.end() || there->second == semantic) && elsewhere == vs.end()) continue;
    const std::string what = usage_text(semantic.first, semantic.second);
    const std::string vs_has =
        there != vs.end() && there->second != semantic
            ? usage_text(there->second.first, there->second.second)
            : fmt::format("nothing ({} is in t{} there)", what, elsewhere->first);
    return fail(std::string(), "not-supported",
                fmt::format("not supported yet: the pixel program reads {} from texcoord slot "
                            "t{}, where the vertex program puts {} (the two stages carry "
                            "different semantics beyond the 2.0 interface)",
                            what, slot, vs_has));
  }
  return ok_status();
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
    if (ins.dst && !ins.dst->rel) rename(ins.dst->file, ins.dst->index); // relative_output_links
    for (SrcOperand& s : ins.src)
      if (!s.rel) rename(s.file, s.index); // v[aL + n] indexes relative_input_links
  }
  return out;
}

RelativeLinks relative_input_links(const Program& program) {
  RelativeLinks out;
  if (program.profile == Profile::vs_3_0) {
    out.resize(16);
    for (const Declaration& d : program.decls)
      if (d.reg.file == RegFile::Input && d.reg.index < out.size())
        out[d.reg.index] = std::pair{RegFile::Input, d.reg.index};
  } else if (program.profile == Profile::ps_3_0) {
    out.resize(10);
    for (const auto& [index, reg] : renames(program, RegFile::Input))
      if (index < out.size()) out[index] = reg;
  }
  return out;
}

RelativeLinks relative_output_links(const Program& program) {
  RelativeLinks out;
  if (program.profile != Profile::vs_3_0) return out;
  out.resize(12);
  for (const auto& [index, reg] : renames(program, RegFile::Output))
    if (index < out.size()) out[index] = reg;
  return out;
}

bool writes_outputs_relatively(const Program& program) {
  for (const Instruction& ins : program.code)
    if (ins.dst && ins.dst->rel && ins.dst->file == RegFile::Output) return true;
  return false;
}

bool reads_inputs_relatively(const Program& program) {
  for (const Instruction& ins : program.code)
    for (const SrcOperand& s : ins.src)
      if (s.rel && s.file == RegFile::Input) return true;
  return false;
}

bool saturates_colors(Profile profile) {
  return profile != Profile::vs_3_0 && profile != Profile::ps_3_0;
}

bool saturates_vertex_colors(Profile vertex, Profile pixel) {
  return saturates_colors(vertex) || saturates_colors(pixel);
}

std::optional<uint32_t> fog_slot(const Program& pixel) {
  if (pixel.profile != Profile::ps_3_0) return std::nullopt;
  const Placement placed = place_extras(pixel, RegFile::Input);
  const auto it = placed.slot.find(Semantic{DeclUsage::Fog, 0});
  if (it == placed.slot.end()) return std::nullopt;
  return it->second;
}

Program feed_fog(const Program& vertex, const Program& pixel) {
  const std::optional<uint32_t> slot = fog_slot(pixel);
  if (!slot || vertex.stage() != ShaderStage::Vertex || linked_file(vertex.profile)) return vertex;
  Program out = vertex;
  for (Instruction& ins : out.code) {
    if (!ins.dst || ins.dst->file != RegFile::RastOut || ins.dst->index != kRastFog) continue;
    // Fog is the lowest component written (`mov oFog, r0.x` writes all four, `oFog.y` one);
    // it goes to .x, the others stay 0. A component-wise source reads that component there.
    const int c = std::countr_zero(static_cast<unsigned>(ins.dst->mask | 0x10)) & 3;
    for (SrcOperand& src : ins.src)
      src.swizzle =
          make_swizzle(swizzle_component(src.swizzle, c), swizzle_component(src.swizzle, 1),
                       swizzle_component(src.swizzle, 2), swizzle_component(src.swizzle, 3));
    ins.dst->file = RegFile::TexCrdOut;
    ins.dst->index = *slot;
    ins.dst->mask = 0x1;
    ins.mods.sat = true; // oFog leaves the vertex stage saturated (NUMERICS.md F6)
  }
  return out;
}

} // namespace tierlift::ir
