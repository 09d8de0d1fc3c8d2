// dcl and def rules: what may be declared in which profile, declarations that are missing
// (inputs and samplers that are used), declaration masks, duplicates, and the warnings for
// declared-but-unread inputs and twice-defined constants.
#include <cmath>
#include <map>
#include <set>

#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::RegFile;

const ir::Declaration* find_decl(const ir::Program& p, RegFile f, uint32_t index) {
  for (const ir::Declaration& d : p.decls)
    if (d.reg.file == f && d.reg.index == index) return &d;
  return nullptr;
}

// vs_3_0: v# inputs and o# outputs with a semantic each (unique per file), s# with a
// texture type; ps_3_0: v# with a semantic, vPos / vFace, s#. No t#, no modifiers in vs_3_0.
void check_decl_sm3(Ctx& c, const ir::Declaration& d,
                    std::set<std::pair<ir::DeclUsage, uint8_t>>& usages) {
  const ir::DstOperand& r = d.reg;
  const bool sampler = r.file == RegFile::Sampler;
  const bool semantic = r.file == RegFile::Input || (c.vs30() && r.file == RegFile::Output);
  if (!sampler && !semantic && !(c.ps30() && r.file == RegFile::Misc)) {
    c.error(r.loc, "declaration",
            fmt::format("{} declares {}; {} cannot be declared", c.pname(),
                        c.vs30() ? "v#, o# and s#" : "v#, vPos, vFace and s#",
                        reg_name(r.file, r.index)));
    return;
  }
  if (sampler && d.sampler_type == ir::SamplerType::Unknown)
    c.error(d.loc, "declaration",
            fmt::format("{} needs a texture type: dcl_2d, dcl_cube or dcl_volume",
                        reg_name(r.file, r.index)));
  if (!sampler && d.sampler_type != ir::SamplerType::Unknown)
    c.error(d.loc, "declaration",
            fmt::format("a texture type (dcl_2d/cube/volume) only applies to s#, not {}",
                        reg_name(r.file, r.index)));
  // Inputs and outputs are told apart by the index space: outputs use usage + 16.
  const uint8_t space = r.file == RegFile::Output ? 16 : 0;
  if (semantic && !usages.insert({d.usage, static_cast<uint8_t>(d.usage_index + space)}).second)
    c.error(d.loc, "declaration",
            fmt::format("two {} declare the same usage and usage index ({})",
                        r.file == RegFile::Output ? "outputs" : "inputs", d.usage_index));
  if (d.mods.sat || d.mods.shift != 0)
    c.error(d.loc, "modifier",
            fmt::format("{} declarations take only _pp and _centroid", c.pname()));
  else if ((c.vs30() || sampler) && (d.mods.pp || d.mods.centroid))
    c.error(d.loc, "modifier",
            c.vs30() ? "vs_3_0 declarations take no modifiers"
                     : "sampler declarations take no _pp or _centroid");
}

void check_decl_shape(Ctx& c) {
  std::set<std::pair<RegFile, uint32_t>> seen;
  std::set<std::pair<ir::DeclUsage, uint8_t>> usages;
  for (const ir::Declaration& d : c.prog.decls) {
    const ir::DstOperand& r = d.reg;
    if (!seen.insert({r.file, r.index}).second)
      c.error(d.loc, "declaration", fmt::format("{} is declared twice", reg_name(r.file, r.index)));
    if (c.sm3()) {
      check_decl_sm3(c, d, usages);
    } else if (c.vs()) {
      if (r.file != RegFile::Input)
        c.error(r.loc, "declaration",
                fmt::format("{} declares only input registers v#; {} cannot be declared", c.pname(),
                            reg_name(r.file, r.index)));
      else if (!usages.insert({d.usage, d.usage_index}).second)
        c.error(
            d.loc, "declaration",
            fmt::format("two inputs declare the same usage and usage index ({})", d.usage_index));
      if (d.usage_index > 15)
        c.error(d.loc, "declaration",
                fmt::format("usage index {} is out of range: the index is 0..15", d.usage_index));
      if (d.mods.pp || d.mods.centroid || d.mods.sat || d.mods.shift != 0)
        c.error(d.loc, "modifier", fmt::format("{} declarations take no modifiers", c.pname()));
    } else if (c.ps2up()) {
      bool sampler = r.file == RegFile::Sampler;
      if (!sampler && r.file != RegFile::Input && r.file != RegFile::Texture)
        c.error(
            r.loc, "declaration",
            fmt::format("ps_2_0 declares v#, t# and s# only, not {}", reg_name(r.file, r.index)));
      else if (sampler && d.sampler_type == ir::SamplerType::Unknown)
        c.error(d.loc, "declaration",
                fmt::format("{} needs a texture type: dcl_2d, dcl_cube or dcl_volume",
                            reg_name(r.file, r.index)));
      else if (!sampler && d.sampler_type != ir::SamplerType::Unknown)
        c.error(d.loc, "declaration",
                fmt::format("a texture type (dcl_2d/cube/volume) only applies to s#, not {}",
                            reg_name(r.file, r.index)));
      if (d.mods.sat || d.mods.shift != 0)
        c.error(d.loc, "modifier", "ps_2_0 declarations take only _pp and _centroid");
      if (sampler && (d.mods.pp || d.mods.centroid))
        c.error(d.loc, "modifier", "sampler declarations take no _pp or _centroid");
    }
  }
}

// vs_1_1 listings written for D3D8 carry no dcl at all: their vertex declaration lived in
// the API, outside the shader (the Irrlicht corpus has such listings). Such a listing is
// taken as declaring every input it reads; once it declares any input, all must be.
bool needs_declaration(const Ctx& c, RegFile f) {
  if (c.vs30()) return f == RegFile::Input || f == RegFile::Sampler;
  if (c.vs()) return f == RegFile::Input && (c.vs2up() || !c.prog.decls.empty());
  if (c.ps30()) return f == RegFile::Input || f == RegFile::Misc || f == RegFile::Sampler;
  if (c.ps2up()) return f == RegFile::Input || f == RegFile::Texture || f == RegFile::Sampler;
  return false;
}

void check_uses(Ctx& c) {
  std::set<std::pair<RegFile, uint32_t>> reported, read;
  for (const ir::Instruction& ins : c.prog.code) {
    for (size_t k = 0; k < ins.src.size(); ++k) {
      const ir::SrcOperand& s = ins.src[k];
      read.insert({s.file, s.index});
      if (!needs_declaration(c, s.file)) continue;
      const ir::Declaration* d = find_decl(c.prog, s.file, s.index);
      if (!d) {
        if (reported.insert({s.file, s.index}).second)
          c.error(s.loc, "declaration",
                  fmt::format("{} is used but not declared; {} requires a dcl for every {}# "
                              "it reads",
                              reg_name(s.file, s.index), c.pname(),
                              reg_name(s.file, 0).substr(0, 1)));
        continue;
      }
      if (!(c.ps2up() || c.vs30()) || s.file == RegFile::Sampler) continue;
      int dim = 3;
      if (k == 0 && ins.src.size() > 1 && ins.src[1].file == RegFile::Sampler)
        dim = sampler_dim(c.prog, ins.src[1].index);
      uint8_t extra = ir::source_read_mask(ins, k, c.target, dim) & ~d->reg.mask;
      if (extra)
        c.error(s.loc, "declaration",
                fmt::format("{} is read, but dcl {}{} declares only {}",
                            reg_comps(s.file, s.index, extra), reg_name(s.file, s.index),
                            ir::mask_text(d->reg.mask), mask_name(d->reg.mask)));
    }
    // texkill's operand is a read too (a destination token in bytecode).
    if (ins.op == ir::Opcode::TexKill && ins.dst) read.insert({ins.dst->file, ins.dst->index});
    // vs_3_0 writes only declared outputs.
    if (c.vs30() && ins.dst && ins.dst->file == RegFile::Output && !ins.dst->rel &&
        !find_decl(c.prog, RegFile::Output, ins.dst->index) &&
        reported.insert({RegFile::Output, ins.dst->index}).second)
      c.error(ins.dst->loc, "declaration",
              fmt::format("{} is written but not declared; vs_3_0 requires a dcl_<usage> for "
                          "every output it writes",
                          reg_name(RegFile::Output, ins.dst->index)));
  }
  for (const ir::Declaration& d : c.prog.decls)
    if ((d.reg.file == RegFile::Input || d.reg.file == RegFile::Texture ||
         d.reg.file == RegFile::Sampler || d.reg.file == RegFile::Misc) &&
        !read.count({d.reg.file, d.reg.index}))
      c.warning(d.loc, "unused-input",
                fmt::format("{} is declared but never read", reg_name(d.reg.file, d.reg.index)));
}

void check_defs(Ctx& c) {
  std::map<std::pair<RegFile, uint32_t>, const ir::ConstDef*> seen;
  for (const ir::ConstDef& d : c.prog.defs) {
    auto [it, fresh] = seen.insert({{d.file, d.index}, &d});
    if (!fresh)
      c.warning(d.loc, "definition",
                fmt::format("{} is defined twice; the last definition (line {}) wins",
                            reg_name(d.file, d.index), d.loc.line));
    if (c.ps1x() && d.file == RegFile::Const)
      for (int k = 0; k < 4; ++k) {
        float v = d.f(k);
        if (std::isfinite(v) && (v > 1.0f || v < -1.0f)) {
          c.warning(d.loc, "definition",
                    fmt::format("{} clamps constants to [-1, 1]; {}.{} = {} reads as {}", c.pname(),
                                reg_name(d.file, d.index), "xyzw"[k], v, v > 0 ? 1 : -1));
          break;
        }
      }
  }
}

} // namespace

int sampler_dim(const ir::Program& p, uint32_t index) {
  const ir::Declaration* d = find_decl(p, RegFile::Sampler, index);
  if (d && d->sampler_type == ir::SamplerType::Tex2D) return 2;
  return 3;
}

void check_declarations(Ctx& c) {
  check_decl_shape(c);
  check_uses(c);
  check_defs(c);
}

} // namespace tierlift::assembly::detail
