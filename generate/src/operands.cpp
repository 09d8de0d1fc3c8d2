// One proposed instruction per table row: destination, write mask, sources of the kinds the
// row's operand columns name, swizzles and modifiers, all at random. Whether the profile
// allows the combination is the validator's call (Builder::accept), not a list kept here.
#include <algorithm>
#include <iterator>

#include "builder.h"
#include "tierlift/ir/profile.h"
#include "tierlift/ir/semantics.h"
#include "tierlift/ir/source_modifiers.h"

namespace tierlift::gen::detail {
namespace {

using ir::Opcode;
using ir::OperandKind;
using ir::RegFile;

struct Candidate {
  RegFile file;
  uint32_t index;
  uint8_t mask; // readable components
};

// The registers of `files` a source may read now.
std::vector<Candidate> candidates(const Builder& b, const std::vector<RegFile>& files) {
  const ir::ProfileLimits& lim = ir::limits(b.profile);
  std::vector<Candidate> out;
  for (RegFile f : files) {
    uint32_t n = 0;
    switch (f) {
    case RegFile::Temp: n = b.temps; break;
    case RegFile::Input:
      n = ir::is_vertex(b.profile) ? 4 : b.profile == ir::Profile::ps_3_0 ? kPixel30Inputs : 2;
      break;
    case RegFile::Misc: n = 2; break;
    case RegFile::Texture:
      n = ir::is_ps1x(b.profile) ? std::min<uint32_t>(lim.texcoords, 4) : 4;
      break;
    case RegFile::Const: n = std::min<uint32_t>(lim.float_consts, 12); break;
    default: break;
    }
    for (uint32_t i = 0; i < n; ++i)
      if (uint8_t m = b.readable(f, i)) out.push_back({f, i, m});
  }
  return out;
}

// A swizzle that reads only components in `mask`.
uint8_t random_swizzle(Rng& r, uint8_t mask, bool scalar) {
  std::vector<int> comps;
  for (int c = 0; c < 4; ++c)
    if (mask & (1 << c)) comps.push_back(c);
  if (scalar || r.chance(0.25)) return ir::replicate_swizzle(r.pick(comps));
  if (mask == ir::kFullMask && r.chance(0.5)) return ir::kIdentitySwizzle;
  return ir::make_swizzle(r.pick(comps), r.pick(comps), r.pick(comps), r.pick(comps));
}

// Any modifier of the table but "!" (booleans only), a quarter of the time.
ir::SrcMod random_modifier(Rng& r) {
  if (!r.chance(0.25)) return ir::SrcMod::None;
  return static_cast<ir::SrcMod>(1 + r.below(static_cast<uint64_t>(ir::SrcMod::AbsNeg)));
}

std::vector<RegFile> readable_files(const Builder& b) {
  if (ir::is_vertex(b.profile)) return {RegFile::Temp, RegFile::Input, RegFile::Const};
  if (b.profile == ir::Profile::ps_3_0)
    return {RegFile::Temp, RegFile::Input, RegFile::Const, RegFile::Misc};
  return {RegFile::Temp, RegFile::Input, RegFile::Const, RegFile::Texture};
}

bool in_loop(const Builder& b) {
  return std::find(b.open.begin(), b.open.end(), Opcode::Loop) != b.open.end();
}

ir::DstOperand random_destination(Builder& b) {
  ir::DstOperand d = dst_reg(RegFile::Temp, b.rng.below(b.temps));
  if (b.profile == ir::Profile::vs_3_0 && b.rng.chance(0.2)) {
    // A declared o# (kVertex30Outputs); inside a loop sometimes o[aL + n].
    d = dst_reg(RegFile::Output, b.rng.below(kVertex30Outputs.size()));
    if (in_loop(b) && b.rng.chance(0.3)) {
      d.index = b.rng.below(2);
      d.rel = ir::RelAddr{RegFile::Loop, 0, {}};
    }
  } else if (ir::is_vertex(b.profile) && b.rng.chance(0.2)) {
    const uint32_t pick = b.rng.below(8);
    d = pick < 2   ? dst_reg(RegFile::AttrOut, pick)
        : pick < 6 ? dst_reg(RegFile::TexCrdOut, pick - 2)
                   : dst_reg(RegFile::RastOut, pick == 6 ? ir::kRastFog : ir::kRastPts, 1);
  } else if (ir::is_ps11_13(b.profile) && b.rng.chance(0.15)) {
    d = dst_reg(RegFile::Texture, b.rng.below(4));
  }
  if (d.file != RegFile::RastOut && b.rng.chance(0.45))
    d.mask = static_cast<uint8_t>(1 + b.rng.below(15));
  return d;
}

void random_instruction_modifiers(Builder& b, ir::Instruction& ins) {
  if (b.profile == ir::Profile::vs_3_0) ins.mods.sat = b.rng.chance(0.1);
  if (ir::is_vertex(b.profile)) return; // vs_3_0's _sat is the only one there
  ins.mods.sat = b.rng.chance(0.2);
  if (ir::is_sm2_or_later(b.profile)) ins.mods.pp = b.rng.chance(0.15);
  if (ir::is_ps1x(b.profile) && b.rng.chance(0.2)) {
    const int8_t shifts[] = {1, 2, 3, -1, -2, -3};
    ins.mods.shift = shifts[b.rng.below(std::size(shifts))];
  }
}

// p0 as a condition: a replicate of a written component (or the whole register when setp
// wrote all four), a third of the time negated.
ir::SrcOperand predicate_source(Builder& b) {
  const uint8_t m = b.readable(RegFile::Predicate, 0);
  const uint8_t swz = m == ir::kFullMask && b.rng.chance(0.3) ? ir::kIdentitySwizzle
                                                              : random_swizzle(b.rng, m, true);
  return src_reg(RegFile::Predicate, 0, swz,
                 b.rng.chance(0.33) ? ir::SrcMod::Not : ir::SrcMod::None);
}

bool compares(Opcode op) {
  return (op >= Opcode::BreakGt && op <= Opcode::BreakLe) ||
         (op >= Opcode::IfGt && op <= Opcode::IfLe);
}

bool is_setp(Opcode op) {
  return op >= Opcode::SetpGt && op <= Opcode::SetpLe;
}

// A source of a non-register-value kind (matrix base, sampler, constants of sincos, ...).
std::optional<ir::SrcOperand> special_source(Builder& b, const ir::OpInfo& row, size_t k) {
  const ir::ProfileLimits& lim = ir::limits(b.profile);
  switch (row.src[k]) {
  case OperandKind::Matrix: {
    const uint32_t rows = ir::op_semantics(row.op).matrix_rows;
    const uint32_t base = b.rng.chance(0.5) ? 0 : kBankConst;
    if (base + rows > lim.float_consts) return std::nullopt;
    return src_reg(RegFile::Const, base);
  }
  case OperandKind::Sampler: return src_reg(RegFile::Sampler, b.rng.below(4));
  case OperandKind::Const:
    if (row.op == Opcode::SinCos) return src_reg(RegFile::Const, kSinCosConst + uint32_t(k) - 1);
    return src_reg(RegFile::Const, b.rng.below(lim.float_consts));
  case OperandKind::Temp: return src_reg(RegFile::Temp, b.rng.below(b.temps));
  case OperandKind::Bool:
    // if and callnz also take p0 (2.x, 3.0) once setp has written it.
    if (b.readable(RegFile::Predicate, 0) && b.rng.chance(0.5)) return predicate_source(b);
    return src_reg(RegFile::ConstBool, b.rng.below(2));
  case OperandKind::Predicate:
    if (!b.readable(RegFile::Predicate, 0)) return std::nullopt;
    return predicate_source(b);
  case OperandKind::Int:
    return src_reg(RegFile::ConstInt, row.op == Opcode::Rep ? kRepCounter : kLoopCounter);
  case OperandKind::LoopReg: return src_reg(RegFile::Loop, 0);
  case OperandKind::Label: {
    const uint32_t l = static_cast<uint32_t>(b.labels.size());
    return src_reg(RegFile::Label, l);
  }
  default: return std::nullopt;
  }
}

} // namespace

std::optional<ir::SrcOperand> random_source(Builder& b, OperandKind kind,
                                            const std::vector<RegFile>& files) {
  std::vector<Candidate> c = candidates(b, files);
  if (c.empty()) return std::nullopt;
  // Temps half of the time when there are any: chains of computed values are the point.
  std::vector<Candidate> temps;
  std::copy_if(c.begin(), c.end(), std::back_inserter(temps),
               [](const Candidate& x) { return x.file == RegFile::Temp; });
  const Candidate& r = (!temps.empty() && b.rng.chance(0.5)) ? b.rng.pick(temps) : b.rng.pick(c);
  ir::SrcOperand s =
      src_reg(r.file, r.index, random_swizzle(b.rng, r.mask, kind == OperandKind::Scalar),
              random_modifier(b.rng));
  // Relative addressing where a0 (or aL, inside a loop) holds a value: c# in vertex
  // programs and ps_3_0 (aL only there), v# in shader model 3 (aL only). A v[aL + n] keeps
  // n small so that it lands on the declared inputs mostly.
  const bool loop = in_loop(b);
  const bool relative_consts = ir::is_vertex(b.profile) || b.profile == ir::Profile::ps_3_0;
  if (r.file == RegFile::Const && relative_consts && b.rng.chance(0.2)) {
    if (loop)
      s.rel = ir::RelAddr{RegFile::Loop, 0, {}};
    else if (ir::is_vertex(b.profile) && (b.written(RegFile::Addr, 0) & 1))
      s.rel = ir::RelAddr{RegFile::Addr, 0, {}};
  }
  if (r.file == RegFile::Input && ir::is_sm3(b.profile) && loop && b.rng.chance(0.25)) {
    s.index = b.rng.below(2);
    s.rel = ir::RelAddr{RegFile::Loop, 0, {}};
  }
  return s;
}

std::vector<ir::Instruction> propose(Builder& b, const ir::OpInfo& row) {
  ir::Instruction ins = make(row.op, std::nullopt);
  if (row.has_dst) {
    ins.dst = random_destination(b);
    if (row.op == Opcode::Mova ||
        (row.op == Opcode::Mov && b.profile == ir::Profile::vs_1_1 && b.rng.chance(0.3)))
      ins.dst = dst_reg(RegFile::Addr, 0, b.rng.chance(0.5) ? 1 : ir::kFullMask);
    // A row that writes fewer components (bem .xy, crs .xyz, m3x2 .xy) often gets its mask.
    if (const uint8_t w = ir::op_writes(row.op, b.profile);
        w != 0 && w != ir::kFullMask && b.rng.chance(0.5))
      ins.dst->mask = w;
    if (row.op == Opcode::SinCos) ins.dst->mask = static_cast<uint8_t>(1 + b.rng.below(3));
    if (is_setp(row.op)) ins.dst = dst_reg(RegFile::Predicate, 0, ins.dst->mask);
  }
  for (size_t k = 0; k < row.num_src; ++k) {
    // if_comp and break_comp compare one component of each source.
    const OperandKind kind = compares(row.op) ? OperandKind::Scalar : row.src[k];
    std::optional<ir::SrcOperand> s = (kind == OperandKind::Vector || kind == OperandKind::Scalar)
                                          ? random_source(b, kind, readable_files(b))
                                          : special_source(b, row, k);
    if (!s) return {};
    ins.src.push_back(*s);
  }
  if (row.op == Opcode::CallNz && b.rng.chance(0.5)) ins.src[1].mod = ir::SrcMod::Not;
  // Modifiers act on a result: none on nop (the validator lets nop_sat through, but the
  // token stream has nowhere to keep it).
  if (row.cls == ir::OpClass::Arith && row.has_dst) random_instruction_modifiers(b, ins);
  // Predicated (2.x, 3.0): "(p0.x) add ...", "(!p0) mov ...", once setp has written p0.
  if (row.cls != ir::OpClass::Flow && ins.dst && ins.dst->file != RegFile::Predicate &&
      b.readable(RegFile::Predicate, 0) && b.rng.chance(0.25))
    ins.pred = predicate_source(b);
  // ps_2_0 texld reads a coordinate register whole: a t# or a temp, no modifier (ps_2_x and
  // ps_3_0 mostly too: their arbitrary swizzles still get a few).
  const bool whole =
      b.profile == ir::Profile::ps_2_0 ||
      (!ir::is_vertex(b.profile) && ir::is_sm2_or_later(b.profile) && b.rng.chance(0.7));
  if (row.cls == ir::OpClass::Texture && whole) {
    if (ins.dst) ins.dst->mask = ir::kFullMask;
    if (!ins.src.empty())
      ins.src[0].swizzle = ir::kIdentitySwizzle, ins.src[0].mod = ir::SrcMod::None;
    ins.mods.pp = b.rng.chance(0.15);
  }
  return {ins};
}

} // namespace tierlift::gen::detail
