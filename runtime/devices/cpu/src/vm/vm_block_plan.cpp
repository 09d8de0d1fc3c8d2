// The block executor's plan (pixel_block.h): which instructions and sources the block path
// takes, which constants are folded once per draw, and which register components start at
// zero. Programs it does not take run on the per-pixel VM.
#include <algorithm>

#include "tierlift/ir/device_pipeline.h"
#include "tierlift/ir/numerics.h"
#include "tierlift/ir/passes.h"
#include "vm_block_internal.h"

namespace tierlift::cpu {

using namespace block;
using ir::Opcode;

namespace {

using Impl = PixelBlockVM::Impl;

std::optional<BlockOp> block_op(Opcode op, ir::OpClass cls) {
  if (cls == ir::OpClass::Arith) return op == Opcode::Nop ? BlockOp::Skip : BlockOp::Arith;
  switch (op) {
  case Opcode::Tex: return BlockOp::Tex;
  case Opcode::TexCoord: return BlockOp::TexCoord;
  case Opcode::TexKill: return BlockOp::TexKill;
  case Opcode::TexLd14: return BlockOp::TexLd14;
  case Opcode::TexCrd: return BlockOp::TexCrd;
  case Opcode::TexLd: return BlockOp::TexLd;
  case Opcode::TexLdP: return BlockOp::TexLdP;
  case Opcode::TexLdB: return BlockOp::TexLdB;
  case Opcode::Phase: return BlockOp::Phase;
  default: return std::nullopt;
  }
}

LaneVec4 splat4(const Vec4& v) {
  LaneVec4 out;
  for (int c = 0; c < 4; ++c) std::fill(std::begin(out.c[c]), std::end(out.c[c]), v[c]);
  return out;
}

// Decides how one source is read; false when the block path does not take it.
bool plan_src(const vm::SrcDesc& s, Impl& im, const ConstantBank& bank, BlockSrc& out) {
  switch (s.kind) {
  case vm::SrcKind::ConstRel:
  case vm::SrcKind::InputRel: return false;
  case vm::SrcKind::Const:
  case vm::SrcKind::Zero: {
    vm::Invocation inv;
    inv.prog = &im.p;
    inv.consts = &bank;
    out.way = SrcWay::Folded;
    out.folded = static_cast<int32_t>(im.folded.size());
    const Vec4 v = vm::fetch_general(s, inv);
    im.folded.push_back(splat4(v));
    out.no_denormal = true;
    for (int c = 0; c < 4; ++c) {
      if (ir::numerics::never_compares_zero(v[c])) out.nonzero |= uint8_t(1u << c);
      if (ir::numerics::signed_zero(v[c])) out.zero |= uint8_t(1u << c);
      if (!ir::numerics::never_compares_zero(v[c]) && !ir::numerics::signed_zero(v[c]))
        out.no_denormal = false;
    }
    return true;
  }
  case vm::SrcKind::Slot: break;
  }
  out.slot = s.slot;
  for (int i = 0; i < 4; ++i) out.comp[i] = s.swz[i];
  if (s.mod == ir::SrcMod::None && !s.clamp_const)
    out.way = SrcWay::Reg;
  else if (s.mod == ir::SrcMod::Neg && !s.clamp_const)
    out.way = SrcWay::Neg;
  else
    out.way = SrcWay::General;
  return true;
}

// Which register components a run may read before it writes them: the inputs run() fills
// count as written; every other component a source may touch (all four of its swizzle, all
// four under _dz/_dw and the other per-lane modifiers) and every component of the returned
// register left unwritten must start at zero, as in the per-pixel VM.
void find_zero_components(Impl& im) {
  std::array<uint8_t, vm::kSlotCount> written{}, need{};
  for (int i = 0; i < 2; ++i)
    if (im.color_reads & (1u << i)) written[vm::kInputBase + i] = 0xF;
  if (!im.p.ps11_13)
    for (int i = 0; i < vm::kTexCount; ++i)
      if (im.tex_reads & (1u << i)) written[vm::kTexBase + i] = 0xF;
  auto reads = [&](const BlockStep& b) {
    for (int k = 0; k < b.step->nsrc; ++k) {
      const BlockSrc& s = b.src[static_cast<size_t>(k)];
      if (s.way == SrcWay::Folded) continue;
      if (b.step->src[static_cast<size_t>(k)].kind != vm::SrcKind::Slot) continue;
      uint8_t comps = 0;
      for (int c = 0; c < 4; ++c) comps |= static_cast<uint8_t>(1u << s.comp[c]);
      if (s.way == SrcWay::General) comps = 0xF;
      need[s.slot] |= static_cast<uint8_t>(comps & ~written[s.slot]);
    }
  };
  auto writes = [&](const BlockStep& b) {
    if (b.step->dst.kind == vm::DstKind::Slot) written[b.step->dst.slot] |= b.step->dst.mask;
  };
  for (size_t i = 0; i < im.steps.size(); ++i) {
    const BlockStep& b = im.steps[i];
    switch (b.op) {
    case BlockOp::Skip: break;
    case BlockOp::ArithPair: // both halves read before either writes
      reads(b);
      reads(im.steps[i + 1]);
      writes(b);
      writes(im.steps[i + 1]);
      break;
    case BlockOp::Phase:
      for (int r = 0; r < 6; ++r) written[vm::kTempBase + r] |= 0x8;
      break;
    case BlockOp::Tex:
    case BlockOp::TexCoord: writes(b); break;
    case BlockOp::TexKill:
      if (!im.p.ps11_13) reads(b);
      break;
    default:
      reads(b);
      writes(b);
      break;
    }
  }
  need[im.out_slot] |= static_cast<uint8_t>(~written[im.out_slot] & 0xF);
  for (int s = 0; s < vm::kSlotCount; ++s)
    for (int c = 0; c < 4; ++c)
      if (need[s] & (1u << c))
        im.zero_components.emplace_back(static_cast<uint16_t>(s), static_cast<uint8_t>(c));
}

// Which steps read only sources that cannot hold a denormal (BlockStep::clean), walking the
// steps in order with, per register component, whether what it holds can be one. At the
// start: zeros, and the colours run() saturates (both clean); the texture coordinates of
// ps_2_0 and the colours of ps_3_0 (not saturated) are not known. A source is clean when it is a
// folded constant with no denormal component, or a plain or negated register read whose four
// swizzled components are clean (a per-lane modifier, or coordinates read in place, count as not
// clean). A write leaves its components clean when
//  - the instruction's result is flushed by its rule (add, sub, mul, mad, lrp and the dot
//    products round through FloatArith, whose results are flushed; slt and sge give 0 or
//    1), or selects among clean sources (mov, abs, min, max, cmp, cnd with every source
//    clean); or
//  - the destination's own steps end in a flush: the ps_1_x range clamp (max ≥ 1) and
//    _sat flush their result, and a flushed value stays clean through the shift and the
//    fixed-point steps (their results are FloatArith results too).
// Texture reads give texels bit for bit and every other instruction counts as not clean.
// This is only used under Denormals::Flush; block_identity_test and executor_identity_test
// hold it to the per-pixel VM with denormal constants, texels and coordinates.
void find_clean_sources(Impl& im) {
  std::array<uint8_t, vm::kSlotCount> clean;
  clean.fill(0xF);
  if (!im.p.ps11_13)
    for (int i = 0; i < vm::kTexCount; ++i) clean[vm::kTexBase + i] = 0;
  if (!im.p.saturate_colors)
    for (int i = 0; i < 2; ++i) clean[vm::kInputBase + i] = 0;
  auto source_clean = [&](const BlockStep& b, int k) {
    const BlockSrc& s = b.src[static_cast<size_t>(k)];
    if (s.way == SrcWay::Folded) return s.no_denormal;
    if (s.way == SrcWay::General || s.input) return false;
    for (int c = 0; c < 4; ++c)
      if (!(clean[s.slot] & (1u << s.comp[c]))) return false;
    return true;
  };
  auto sources_clean = [&](const BlockStep& b) {
    for (int k = 0; k < b.step->nsrc; ++k)
      if (!source_clean(b, k)) return false;
    return true;
  };
  auto result_clean = [&](const BlockStep& b) {
    switch (b.step->ins->op) {
    case Opcode::Add:
    case Opcode::Sub:
    case Opcode::Mul:
    case Opcode::Mad:
    case Opcode::Lrp:
    case Opcode::Dp3:
    case Opcode::Dp4:
    case Opcode::Dp2Add:
    case Opcode::Slt:
    case Opcode::Sge: return true;
    case Opcode::Mov:
    case Opcode::Abs:
    case Opcode::Min:
    case Opcode::Max:
    case Opcode::Cmp:
    case Opcode::Cnd: return b.clean;
    default: return false;
    }
  };
  auto write = [&](const BlockStep& b, bool result) {
    const vm::DstDesc& d = b.step->dst;
    if (d.kind != vm::DstKind::Slot) return;
    const bool flushed = (d.range && d.max_value >= 1.0f) || d.sat;
    if (result || flushed)
      clean[d.slot] |= d.mask;
    else
      clean[d.slot] &= static_cast<uint8_t>(~d.mask);
  };
  for (size_t i = 0; i < im.steps.size(); ++i) {
    BlockStep& b = im.steps[i];
    switch (b.op) {
    case BlockOp::Skip: break;
    case BlockOp::Arith:
      b.clean = sources_clean(b);
      write(b, result_clean(b));
      break;
    case BlockOp::ArithPair: { // both halves read before either writes
      BlockStep& second = im.steps[i + 1];
      b.clean = sources_clean(b);
      second.clean = sources_clean(second);
      write(b, result_clean(b));
      write(second, result_clean(second));
      break;
    }
    case BlockOp::Phase:
      for (int r = 0; r < 6; ++r) clean[vm::kTempBase + r] |= 0x8; // w set to 0
      break;
    case BlockOp::TexKill: break;
    default: write(b, false); break; // texture reads and coordinates
    }
  }
}

// Whether a step may compute straight into its destination register: a plain register write
// (no shift, clamp or quantising between result and register), of all four components for a
// texture read (which writes all four), and, for arithmetic, no source that reads a component
// of that register another written component may already have replaced. Lane loops write
// component c at lane l after reading lane l of its sources, so a source that reads the
// written component itself, or one the mask leaves alone, sees the value before the
// instruction, as through the copy. A co-issued pair keeps the copy (both halves read first).
bool direct_write(const BlockStep& b) {
  const vm::DstDesc& d = b.step->dst;
  if (d.kind != vm::DstKind::Slot || !d.plain) return false;
  const auto reads_dst = [&](const BlockSrc& s) {
    return (s.way == SrcWay::Reg || s.way == SrcWay::Neg) && s.slot == d.slot;
  };
  if (b.op == BlockOp::Tex) return d.mask == 0xF;
  if (b.op == BlockOp::TexLd) return d.mask == 0xF && !reads_dst(b.src[0]);
  if (b.op != BlockOp::Arith) return false;
  for (int k = 0; k < b.step->nsrc; ++k) {
    const BlockSrc& s = b.src[static_cast<size_t>(k)];
    if (!reads_dst(s)) continue;
    for (int c = 0; c < 4; ++c) {
      const int r = s.comp[c];
      if ((d.mask & (1 << c)) && r != c && (d.mask & (1 << r))) return false;
    }
  }
  return true;
}

// Where t# can be read in place from the block's input (BlockSrc::input): outside ps_1_1–1_3
// (whose texture instructions fill t#) and when no step writes the register, so every read
// sees the coordinates run() would have copied. The others are still copied.
void find_input_reads(Impl& im) {
  im.tex_copies = 0;
  if (im.p.ps11_13) return;
  std::array<bool, vm::kSlotCount> written{};
  for (const BlockStep& b : im.steps)
    if (b.op != BlockOp::Skip && b.step->dst.kind == vm::DstKind::Slot)
      written[b.step->dst.slot] = true;
  for (BlockStep& b : im.steps)
    for (int k = 0; k < b.step->nsrc; ++k) {
      BlockSrc& s = b.src[static_cast<size_t>(k)];
      if (s.way == SrcWay::Folded || s.slot < vm::kTexBase ||
          s.slot >= vm::kTexBase + vm::kTexCount)
        continue;
      if (!written[s.slot])
        s.input = true;
      else
        im.tex_copies |= static_cast<uint8_t>(1u << (s.slot - vm::kTexBase));
    }
  im.tex_copies &= im.tex_reads;
}

} // namespace

std::unique_ptr<PixelBlockVM> PixelBlockVM::create(const ir::Program& program,
                                                   const ir::Conventions& conventions,
                                                   const ConstantBank& constants, bool coords_2d) {
  if (program.stage() != ir::ShaderStage::Pixel) return nullptr;
  auto im = std::make_unique<Impl>();
  // The device pipeline (ir/device_pipeline.h): products with a ±0 constant factor read
  // nothing else, and what fed only them is dropped — the same results for these constants.
  ir::Result<ir::DeviceProgram> prepared = ir::prepare_for_device(program, constants.f);
  if (!prepared) return nullptr;
  const ir::Program& run = prepared->specialised ? *prepared->specialised : program;
  ir::Result<vm::Prepared> steps = vm::prepare(run, conventions);
  if (!steps) return nullptr;
  im->p = std::move(*steps);
  const vm::Prepared& p = im->p;
  const size_t n = p.steps.size();
  im->steps.resize(n);
  std::vector<bool> read(vm::kSlotCount, false);
  for (size_t i = 0; i < n; ++i) {
    const vm::Step& st = p.steps[i];
    BlockStep& b = im->steps[i];
    b.step = &st;
    const ir::Opcode op = st.ins->op;
    std::optional<BlockOp> bop = block_op(op, ir::op_info(op).cls);
    if (!bop || st.rows) return nullptr;
    if (st.gradient) return nullptr; // dsx/dsy read the 2x2 quad: ShaderVM::run_quad
    // Predication and setp (2.x, 3.0) run per pixel only.
    if (st.ins->pred || st.exec == vm::exec_setp) return nullptr;
    b.op = *bop;
    if (b.op == BlockOp::Arith && st.exec == vm::exec_arith_pair) b.op = BlockOp::ArithPair;
    if (st.dst.kind == vm::DstKind::AddrFloor || st.dst.kind == vm::DstKind::AddrRound ||
        st.dst.kind == vm::DstKind::OutputRel)
      return nullptr;
    // Operands the executor reads (texkill reads its register as src[0]).
    const bool reads_srcs = b.op != BlockOp::Tex && b.op != BlockOp::TexCoord &&
                            !(b.op == BlockOp::TexKill && p.ps11_13) && b.op != BlockOp::Phase;
    if (reads_srcs)
      for (int k = 0; k < st.nsrc; ++k) {
        if (!plan_src(st.src[static_cast<size_t>(k)], *im, constants,
                      b.src[static_cast<size_t>(k)]))
          return nullptr;
        const vm::SrcDesc& sd = st.src[static_cast<size_t>(k)];
        if (sd.kind != vm::SrcKind::Slot) continue;
        if (sd.slot >= vm::kMiscBase) return nullptr; // vPos, vFace: per pixel only
        read[sd.slot] = true;
        if (sd.slot < vm::kTexBase || sd.slot >= vm::kTexBase + vm::kTexCount) continue;
        // The components of t# this operand can pass on: its swizzle's, all four under a
        // per-lane modifier (_dz/_dw read z or w); only u and v when a plain coordinate goes
        // straight to a texture unit that reads 2D coordinates.
        const BlockSrc& bs = b.src[static_cast<size_t>(k)];
        uint32_t comps = 0;
        for (int c = 0; c < 4; ++c) comps |= 1u << bs.comp[c];
        if (bs.way == SrcWay::General) comps = 0xF;
        if (coords_2d && k == 0 && bs.way == SrcWay::Reg &&
            (b.op == BlockOp::TexLd || b.op == BlockOp::TexLd14))
          comps = (1u << bs.comp[0]) | (1u << bs.comp[1]);
        im->tex_components |= comps << (4 * (sd.slot - vm::kTexBase));
      }
    if (!reads_srcs && b.op != BlockOp::Phase && st.aux >= 0 && st.aux < 8)
      im->tex_components |= 0xFu << (4 * st.aux); // TC(m), all of it
  }
  // The second half of a pair runs inside the first.
  for (size_t i = 0; i + 1 < n; ++i)
    if (im->steps[i].op == BlockOp::ArithPair) im->steps[i + 1].op = BlockOp::Skip;
  for (BlockStep& b : im->steps) b.direct = direct_write(b);

  for (int i = 0; i < 2; ++i)
    if (read[vm::kInputBase + i]) im->color_reads |= static_cast<uint8_t>(1u << i);
  for (int i = 0; i < vm::kTexCount; ++i)
    if (im->tex_components & (0xFu << (4 * i))) im->tex_reads |= static_cast<uint8_t>(1u << i);
  im->out_slot = static_cast<uint16_t>(p.ps1x ? vm::kTempBase : vm::kOutBase + vm::kOutC0);
  find_zero_components(*im);
  find_input_reads(*im);
  find_clean_sources(*im);
  return std::unique_ptr<PixelBlockVM>(new PixelBlockVM(std::move(im)));
}

} // namespace tierlift::cpu
