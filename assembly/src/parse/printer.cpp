// ir::Program → canonical text. Every choice here is made so that parse(print(p)) is p:
// one spelling per construct, floats in shortest round-trip form, NaNs as raw bits.
#include "tierlift/assembly/printer.h"

#include <bit>
#include <cmath>

#include <fmt/format.h>

#include "tierlift/assembly/preprocessor.h"
#include "tierlift/ir/source_modifiers.h"

namespace tierlift::assembly {
namespace {

std::string_view usage_name(ir::DeclUsage u) {
  static constexpr std::string_view names[] = {
      "position", "blendweight", "blendindices", "normal", "psize", "texcoord", "tangent",
      "binormal", "tessfactor",  "positiont",    "color",  "fog",   "depth",    "sample"};
  auto i = static_cast<size_t>(u);
  return i < std::size(names) ? names[i] : "position";
}

std::string float_text(uint32_t raw) {
  float f = std::bit_cast<float>(raw);
  // NaN payloads have no decimal spelling; the parser reads 0x… as the raw pattern.
  if (std::isnan(f)) return fmt::format("0x{:08x}", raw);
  return fmt::format("{}", f); // shortest text that reads back to the same float
}

// "c", "v", "oT": the register's name without its index, for c[a0.x + 4].
std::string file_prefix(ir::RegFile f) {
  std::string name = ir::register_name(f, 0);
  if (!name.empty() && name.back() == '0') name.pop_back();
  return name;
}

std::string_view src_mod_suffix(ir::SrcMod m) {
  return ir::src_mod_info(m).suffix;
}

std::string_view src_mod_prefix(ir::SrcMod m) {
  return ir::src_mod_info(m).prefix;
}

// The address register's swizzle: replicates as one letter (a0.x), the identity as
// nothing, anything else with its four letters.
std::string rel_swizzle_text(uint8_t swz) {
  if (swz == ir::kIdentitySwizzle) return "";
  if (ir::is_replicate(swz)) return fmt::format(".{}", "xyzw"[swz & 3]);
  std::string out = ".";
  for (int i = 0; i < 4; ++i) out += "xyzw"[ir::swizzle_component(swz, i)];
  return out;
}

// "c[a0.x + 4]", "v[aL]", "o[a0 + 12]".
std::string relative_text(ir::RegFile file, uint32_t index, const ir::RelAddr& rel) {
  // a0 as the address token has it: "a0" (identity), "a0.x", or "a0.xyww" as written.
  std::string reg = rel.file == ir::RegFile::Loop ? std::string("aL")
                                                  : "a0" + rel_swizzle_text(rel.token_swizzle());
  return index ? fmt::format("{}[{} + {}]", file_prefix(file), reg, index)
               : fmt::format("{}[{}]", file_prefix(file), reg);
}

std::string src_text(const ir::SrcOperand& s) {
  std::string out(src_mod_prefix(s.mod));
  if (s.rel) {
    out += relative_text(s.file, s.index, *s.rel);
  } else {
    out += ir::register_name(s.file, s.index);
  }
  out += src_mod_suffix(s.mod);
  out += ir::swizzle_text(s.swizzle);
  return out;
}

std::string dst_text(const ir::DstOperand& d) {
  std::string reg =
      d.rel ? relative_text(d.file, d.index, *d.rel) : ir::register_name(d.file, d.index);
  return reg + ir::mask_text(d.mask);
}

// Fixed order: shift, _sat, _pp, _centroid.
std::string mods_text(const ir::InstrMods& m) {
  static constexpr std::string_view shifts[] = {"_d8", "_d4", "_d2", "", "_x2", "_x4", "_x8"};
  std::string out;
  if (m.shift >= -3 && m.shift <= 3) out += shifts[m.shift + 3];
  if (m.sat) out += "_sat";
  if (m.pp) out += "_pp";
  if (m.centroid) out += "_centroid";
  return out;
}

std::string decl_text(const ir::Declaration& d, ir::Profile profile) {
  std::string out = "dcl";
  // Vertex inputs and outputs and ps_3_0 inputs always name their usage; index 0 is left
  // out (dcl_texcoord = dcl_texcoord0).
  bool usage = (ir::is_vertex(profile) && d.reg.file != ir::RegFile::Sampler) ||
               (profile == ir::Profile::ps_3_0 && d.reg.file == ir::RegFile::Input) ||
               d.usage != ir::DeclUsage::Position || d.usage_index != 0;
  if (usage) {
    out += fmt::format("_{}", usage_name(d.usage));
    if (d.usage_index) out += fmt::format("{}", d.usage_index);
  }
  switch (d.sampler_type) {
  case ir::SamplerType::Tex2D: out += "_2d"; break;
  case ir::SamplerType::Cube: out += "_cube"; break;
  case ir::SamplerType::Volume: out += "_volume"; break;
  default: break;
  }
  out += mods_text(d.mods);
  return out + " " + dst_text(d.reg);
}

std::string def_text(const ir::ConstDef& d) {
  switch (d.file) {
  case ir::RegFile::ConstInt:
    return fmt::format("defi i{}, {}, {}, {}, {}", d.index, d.i(0), d.i(1), d.i(2), d.i(3));
  case ir::RegFile::ConstBool:
    return fmt::format("defb b{}, {}", d.index, d.b() ? "true" : "false");
  default:
    return fmt::format("def c{}, {}, {}, {}, {}", d.index, float_text(d.raw[0]),
                       float_text(d.raw[1]), float_text(d.raw[2]), float_text(d.raw[3]));
  }
}

// Eight words a line: "//!comment 0x42415443 ..." then "//!comment+ ..." lines.
std::string comment_text(const ir::CommentBlock& c) {
  constexpr size_t kWordsPerLine = 8;
  std::string out(kCommentBlockMark);
  for (size_t i = 0; i < c.words.size(); ++i) {
    if (i > 0 && i % kWordsPerLine == 0) out += fmt::format("\n{}+", kCommentBlockMark);
    out += fmt::format(" 0x{:08x}", c.words[i]);
  }
  return out;
}

} // namespace

std::string print_comment_block(const ir::CommentBlock& c) {
  return comment_text(c);
}

std::string print_declaration(const ir::Declaration& d, ir::Profile profile) {
  return decl_text(d, profile);
}

std::string print_definition(const ir::ConstDef& d) {
  return def_text(d);
}

std::string print_instruction(const ir::Instruction& ins, ir::Profile /*profile*/) {
  std::string out = ins.coissue ? "+" : "";
  // Appended piece by piece: "(" + temporary trips GCC 12's false -Wrestrict at -O3.
  if (ins.pred) {
    out += '(';
    out += src_text(*ins.pred);
    out += ") ";
  }
  out += ir::op_info(ins.op).mnemonic;
  out += mods_text(ins.mods);
  bool first = true;
  auto sep = [&] {
    out += first ? " " : ", ";
    first = false;
  };
  if (ins.dst) sep(), out += dst_text(*ins.dst);
  for (const ir::SrcOperand& s : ins.src) sep(), out += src_text(s);
  return out;
}

std::string print_program(const ir::Program& p) {
  std::string out(ir::profile_name(p.profile));
  out += '\n';
  for (const auto& st : p.statements()) {
    switch (st.kind) {
    case ir::Program::Statement::Kind::Decl: out += decl_text(p.decls[st.index], p.profile); break;
    case ir::Program::Statement::Kind::Def: out += def_text(p.defs[st.index]); break;
    case ir::Program::Statement::Kind::Code:
      out += print_instruction(p.code[st.index], p.profile);
      break;
    case ir::Program::Statement::Kind::Comment: out += comment_text(p.comments[st.index]); break;
    }
    out += '\n';
  }
  return out;
}

} // namespace tierlift::assembly
