// The block executor (pixel_block.h): the prepared program of the per-pixel VM, run one
// instruction at a time over kBlockLanes pixels. Every value is computed by the functions the
// per-pixel VM calls (ir/numerics.h, vm::modify_src, vm::dst_transform, the VM's compute table),
// lane by lane, in the same order and under the program's denormal mode (NUMERICS.md rule 13:
// everything below is a template on it, chosen once per run), so the two executors agree bit
// for bit; what the block
// saves is the decoding, the dispatch and the copies, paid once per block instead of per pixel,
// and its lane loops are plain enough for the compiler to vectorise.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "tierlift/cpu/pixel_block.h"
#include "tierlift/ir/numerics.h"
#include "vm_internal.h"

namespace tierlift::cpu {

namespace num = ir::numerics;
using ir::Opcode;
using num::Denormals;

namespace {

constexpr int L = kBlockLanes;

enum class BlockOp : uint8_t {
  Skip, // nop, the second half of a co-issued pair (run by the first)
  Arith,
  ArithPair,
  Tex,      // ps_1_1–1_3 tex
  TexCoord, // ps_1_1–1_3 texcoord
  TexKill,
  TexLd14,
  TexCrd,
  TexLd,
  TexLdP,
  TexLdB,
  Phase,
};

// How a source operand reaches the lanes.
enum class SrcWay : uint8_t {
  Reg,     // a register's lane arrays, swizzle applied by choosing arrays
  Folded,  // a constant (or a read-as-zero operand), fetched and modified once per draw
  Neg,     // a register negated after the swizzle
  General, // per lane through vm::modify_src
};

struct BlockSrc {
  SrcWay way = SrcWay::Folded;
  uint16_t slot = 0;
  uint8_t comp[4] = {0, 1, 2, 3};
  int32_t folded = -1;
};

struct BlockStep {
  const vm::Step* step = nullptr;
  BlockOp op = BlockOp::Skip;
  std::array<BlockSrc, 4> src{};
};

struct View {
  const float* c[4];
};

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

} // namespace

struct PixelBlockVM::Impl {
  vm::Prepared p;
  std::vector<BlockStep> steps;
  std::vector<LaneVec4> folded;
  // Register components that may be read (or returned) before the program writes them: the
  // per-pixel VM starts every register at zero, so these are zeroed per block.
  std::vector<std::pair<uint16_t, uint8_t>> zero_components;
  uint8_t color_reads = 0, tex_reads = 0;
  uint32_t tex_components = 0; // bits 4r..4r+3: the components of TC(r) that matter
  uint16_t out_slot = 0;
};

struct PixelBlockVM::Scratch {
  LaneVec4 reg[vm::kSlotCount]{};
  LaneVec4 src[2][4]{}; // sources modified per lane: [pair half][operand]
  LaneVec4 dst[2]{};    // results before the store: [pair half]
  LaneVec4 coord{};     // texture coordinates built per lane
  Lanes zero{}, one{};
};

namespace {

using Impl = PixelBlockVM::Impl;
using Scratch = PixelBlockVM::Scratch;

LaneVec4 splat4(const Vec4& v) {
  LaneVec4 out;
  for (int c = 0; c < 4; ++c) std::fill(std::begin(out.c[c]), std::end(out.c[c]), v[c]);
  return out;
}

// Decides how one source is read; false when the block path does not take it.
bool plan_src(const vm::SrcDesc& s, Impl& im, const ConstantBank& bank, BlockSrc& out) {
  switch (s.kind) {
  case vm::SrcKind::ConstRel: return false;
  case vm::SrcKind::Const:
  case vm::SrcKind::Zero: {
    vm::Invocation inv;
    inv.prog = &im.p;
    inv.consts = &bank;
    out.way = SrcWay::Folded;
    out.folded = static_cast<int32_t>(im.folded.size());
    im.folded.push_back(splat4(vm::fetch_general(s, inv)));
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

template <Denormals D>
View fetch(const Impl& im, const BlockStep& b, int k, int half, Scratch& sc) {
  const BlockSrc& s = b.src[static_cast<size_t>(k)];
  View v;
  switch (s.way) {
  case SrcWay::Folded:
    for (int c = 0; c < 4; ++c) v.c[c] = im.folded[static_cast<size_t>(s.folded)].c[c];
    return v;
  case SrcWay::Reg:
    for (int c = 0; c < 4; ++c) v.c[c] = sc.reg[s.slot].c[s.comp[c]];
    return v;
  case SrcWay::Neg: {
    LaneVec4& out = sc.src[half][k];
    for (int c = 0; c < 4; ++c) {
      const float* r = sc.reg[s.slot].c[s.comp[c]];
      for (int l = 0; l < L; ++l) out.c[c][l] = -r[l];
      v.c[c] = out.c[c];
    }
    return v;
  }
  case SrcWay::General: {
    LaneVec4& out = sc.src[half][k];
    const LaneVec4& r = sc.reg[s.slot];
    const vm::SrcDesc& d = b.step->src[static_cast<size_t>(k)];
    for (int l = 0; l < L; ++l) {
      Vec4 x = vm::modify_src<D>(d, {r.c[0][l], r.c[1][l], r.c[2][l], r.c[3][l]});
      for (int c = 0; c < 4; ++c) out.c[c][l] = x[c];
    }
    for (int c = 0; c < 4; ++c) v.c[c] = out.c[c];
    return v;
  }
  }
  return v;
}

// d[c][l] = f(a[c][l], …) for every component and lane: one rule function per lane. The
// result never shares memory with a source (it goes to Scratch::dst). "unroll 1" keeps GCC
// from unrolling the lane loop completely before the loop vectoriser sees it: the vectoriser
// if-converts the rule functions' selects, the straight-line vectoriser after unrolling
// cannot.
template <typename F> void lanes1(LaneVec4& d, const View& a, F f) {
  for (int c = 0; c < 4; ++c) {
    float* __restrict o = d.c[c];
    const float* __restrict x = a.c[c];
#pragma GCC unroll 1
    for (int l = 0; l < L; ++l) o[l] = f(x[l]);
  }
}
template <typename F> void lanes2(LaneVec4& d, const View& a, const View& b, F f) {
  for (int c = 0; c < 4; ++c) {
    float* __restrict o = d.c[c];
    const float* __restrict x = a.c[c];
    const float* __restrict y = b.c[c];
#pragma GCC unroll 1
    for (int l = 0; l < L; ++l) o[l] = f(x[l], y[l]);
  }
}
template <typename F> void lanes3(LaneVec4& d, const View& a, const View& b, const View& e, F f) {
  for (int c = 0; c < 4; ++c) {
    float* __restrict o = d.c[c];
    const float* __restrict x = a.c[c];
    const float* __restrict y = b.c[c];
    const float* __restrict z = e.c[c];
#pragma GCC unroll 1
    for (int l = 0; l < L; ++l) o[l] = f(x[l], y[l], z[l]);
  }
}
// A dot product per lane, splatted to all four components (as the VM's splat).
template <typename F> void lanes_dot(LaneVec4& d, const View& a, const View& b, F dot) {
  for (int l = 0; l < L; ++l) {
    const float x[4] = {a.c[0][l], a.c[1][l], a.c[2][l], a.c[3][l]};
    const float y[4] = {b.c[0][l], b.c[1][l], b.c[2][l], b.c[3][l]};
    const float r = dot(x, y, l);
    for (int c = 0; c < 4; ++c) d.c[c][l] = r;
  }
}

// Every other arithmetic instruction: the VM's own compute function, lane by lane.
void compute_per_lane(const vm::Step& st, const View* s, int n, LaneVec4& d, vm::Invocation& inv) {
  for (int l = 0; l < n; ++l) {
    Vec4 in[5];
    for (int k = 0; k < st.nsrc; ++k)
      in[k] = {s[k].c[0][l], s[k].c[1][l], s[k].c[2][l], s[k].c[3][l]};
    Vec4 r{0, 0, 0, 0};
    st.compute(st, in, r, inv);
    for (int c = 0; c < 4; ++c) d.c[c][l] = r[c];
  }
}

// The VM's compute functions of the same opcodes (vm_arith.cpp) call the same rules with the
// same D; compute_per_lane calls the VM's own, taken from the table of the program's mode.
template <Denormals D>
void compute(const Impl& im, const BlockStep& b, int half, int n, Scratch& sc, LaneVec4& d,
             vm::Invocation& inv) {
  const vm::Step& st = *b.step;
  View s[4];
  for (int k = 0; k < st.nsrc; ++k) s[k] = fetch<D>(im, b, k, half, sc);
  switch (st.ins->op) {
  case Opcode::Mov: lanes1(d, s[0], [](float a) { return a; }); return;
  case Opcode::Add:
    lanes2(d, s[0], s[1], [](float a, float e) { return num::legacy_add<D>(a, e); });
    return;
  case Opcode::Sub:
    lanes2(d, s[0], s[1], [](float a, float e) { return num::legacy_sub<D>(a, e); });
    return;
  case Opcode::Mul:
    lanes2(d, s[0], s[1], [](float a, float e) { return num::legacy_mul<D>(a, e); });
    return;
  case Opcode::Mad:
    lanes3(d, s[0], s[1], s[2],
           [](float a, float e, float f) { return num::legacy_mad<D>(a, e, f); });
    return;
  case Opcode::Min:
    lanes2(d, s[0], s[1], [](float a, float e) { return num::legacy_min<D>(a, e); });
    return;
  case Opcode::Max:
    lanes2(d, s[0], s[1], [](float a, float e) { return num::legacy_max<D>(a, e); });
    return;
  case Opcode::Slt:
    lanes2(d, s[0], s[1], [](float a, float e) { return num::legacy_slt<D>(a, e); });
    return;
  case Opcode::Sge:
    lanes2(d, s[0], s[1], [](float a, float e) { return num::legacy_sge<D>(a, e); });
    return;
  case Opcode::Lrp:
    lanes3(d, s[0], s[1], s[2],
           [](float a, float e, float f) { return num::legacy_lrp<D>(a, e, f); });
    return;
  case Opcode::Cmp:
    lanes3(d, s[0], s[1], s[2],
           [](float a, float e, float f) { return num::legacy_cmp<D>(a, e, f); });
    return;
  case Opcode::Cnd:
    lanes3(d, s[0], s[1], s[2],
           [](float a, float e, float f) { return num::legacy_cnd<D>(a, e, f); });
    return;
  case Opcode::Abs: lanes1(d, s[0], [](float a) { return std::fabs(a); }); return;
  case Opcode::Dp3:
    lanes_dot(d, s[0], s[1],
              [](const float* x, const float* y, int) { return num::legacy_dp3<D>(x, y); });
    return;
  case Opcode::Dp4:
    lanes_dot(d, s[0], s[1],
              [](const float* x, const float* y, int) { return num::legacy_dp4<D>(x, y); });
    return;
  case Opcode::Dp2Add: {
    const float* w = s[2].c[3]; // the scalar operand reads its 4th swizzle slot
    lanes_dot(d, s[0], s[1], [w](const float* x, const float* y, int l) {
      return num::legacy_add<D>(num::legacy_dp2<D>(x, y), w[l]);
    });
    return;
  }
  default: compute_per_lane(st, s, n, d, inv); return;
  }
}

template <Denormals D> void store(const vm::DstDesc& d, const LaneVec4& v, Scratch& sc) {
  if (d.kind != vm::DstKind::Slot) return; // address registers never reach the block path
  LaneVec4& r = sc.reg[d.slot];
  for (int c = 0; c < 4; ++c) {
    if (!(d.mask & (1 << c))) continue;
    if (d.plain) {
      std::memcpy(r.c[c], v.c[c], sizeof(Lanes));
    } else {
      for (int l = 0; l < L; ++l) r.c[c][l] = vm::dst_transform<D>(d, v.c[c][l]);
    }
  }
}

// TC(m) as the per-pixel VM's tc(): the interpolated set, zeros outside 0..7.
View tex_coord(const PixelBlockInput& in, int32_t m, const Scratch& sc) {
  View v;
  for (int c = 0; c < 4; ++c) v.c[c] = (m >= 0 && m < 8) ? in.tex[m].c[c] : sc.zero;
  return v;
}

// The per-pixel VM's sample(): stage ≥ 0 always holds here (a destination number).
void sample(const TextureUnit& t, int32_t stage, const View& coord, const float* bias, int n,
            LaneVec4& out) {
  t.sample_block(static_cast<uint32_t>(stage), coord.c, bias, n, out.c);
}

// x/w, y/w, z/w, 1 (D3DTTFF_PROJECTED and texldp), per lane as the VM divides.
template <Denormals D> View projected(const View& c, Scratch& sc) {
  LaneVec4& out = sc.coord;
  for (int l = 0; l < L; ++l) {
    const float w = c.c[3][l];
    out.c[0][l] = num::legacy_div<D>(c.c[0][l], w);
    out.c[1][l] = num::legacy_div<D>(c.c[1][l], w);
    out.c[2][l] = num::legacy_div<D>(c.c[2][l], w);
    out.c[3][l] = 1.0f;
  }
  return {{out.c[0], out.c[1], out.c[2], out.c[3]}};
}

template <Denormals D> void kill_lanes(const View& v, int comps, int n, PixelBlockOutput& out) {
  for (int l = 0; l < n; ++l)
    for (int i = 0; i < comps; ++i)
      if (num::dz<D>(v.c[i][l]) < 0.0f) out.discarded[static_cast<size_t>(l)] = true;
}

} // namespace

namespace {

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

} // namespace

std::unique_ptr<PixelBlockVM> PixelBlockVM::create(const ir::Program& program,
                                                   const ir::Conventions& conventions,
                                                   const ConstantBank& constants, bool coords_2d) {
  if (program.stage() != ir::ShaderStage::Pixel) return nullptr;
  auto im = std::make_unique<Impl>();
  try {
    im->p = vm::prepare(program, conventions);
  } catch (const std::invalid_argument&) {
    return nullptr;
  }
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
    b.op = *bop;
    if (b.op == BlockOp::Arith && st.exec == vm::exec_arith_pair) b.op = BlockOp::ArithPair;
    if (st.dst.kind == vm::DstKind::AddrFloor || st.dst.kind == vm::DstKind::AddrRound)
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

  for (int i = 0; i < 2; ++i)
    if (read[vm::kInputBase + i]) im->color_reads |= static_cast<uint8_t>(1u << i);
  for (int i = 0; i < vm::kTexCount; ++i)
    if (im->tex_components & (0xFu << (4 * i))) im->tex_reads |= static_cast<uint8_t>(1u << i);
  im->out_slot = static_cast<uint16_t>(p.ps1x ? vm::kTempBase : vm::kOutBase + vm::kOutC0);
  find_zero_components(*im);
  return std::unique_ptr<PixelBlockVM>(new PixelBlockVM(std::move(im)));
}

PixelBlockVM::PixelBlockVM(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PixelBlockVM::~PixelBlockVM() = default;

uint8_t PixelBlockVM::color_reads() const {
  return impl_->color_reads;
}
uint8_t PixelBlockVM::tex_reads() const {
  return impl_->tex_reads;
}
uint32_t PixelBlockVM::tex_components() const {
  return impl_->tex_components;
}

std::unique_ptr<PixelBlockVM::Scratch, void (*)(PixelBlockVM::Scratch*)>
PixelBlockVM::make_scratch() const {
  auto* s = new Scratch();
  std::fill(std::begin(s->one), std::end(s->one), 1.0f);
  return {s, [](Scratch* p) { delete p; }};
}

namespace {

template <Denormals D>
void run_steps(const Impl& im, const PixelBlockInput& in, const TextureUnit& textures,
               PixelBlockOutput& out, Scratch& sc) {
  const vm::Prepared& p = im.p;
  const int n = std::clamp(in.count, 0, L);
  for (const auto& [slot, c] : im.zero_components)
    std::fill(std::begin(sc.reg[slot].c[c]), std::end(sc.reg[slot].c[c]), 0.0f);
  // The inputs as run_pixel sets them: colours saturated; t# are the coordinates except in
  // ps_1_1–1_3, where texture instructions fill them.
  for (int i = 0; i < 2; ++i)
    if (im.color_reads & (1u << i))
      for (int c = 0; c < 4; ++c)
        for (int l = 0; l < L; ++l)
          sc.reg[vm::kInputBase + i].c[c][l] = num::legacy_saturate<D>(in.color[i].c[c][l]);
  if (!p.ps11_13)
    for (int i = 0; i < vm::kTexCount; ++i)
      if (im.tex_reads & (1u << i)) sc.reg[vm::kTexBase + i] = in.tex[i];
  out.discarded.fill(false);

  vm::Invocation inv; // what the VM's compute functions may consult (expp, bem)
  inv.prog = &p;
  inv.tex = &textures;
  LaneVec4& d0 = sc.dst[0];
  for (const BlockStep& b : im.steps) {
    const vm::Step& st = *b.step;
    switch (b.op) {
    case BlockOp::Skip: break;
    case BlockOp::Arith:
      compute<D>(im, b, 0, n, sc, d0, inv);
      store<D>(st.dst, d0, sc);
      break;
    case BlockOp::ArithPair: {
      // Both halves read before either writes.
      const BlockStep& second = (&b)[1];
      compute<D>(im, b, 0, n, sc, d0, inv);
      compute<D>(im, second, 1, n, sc, sc.dst[1], inv);
      store<D>(st.dst, d0, sc);
      store<D>(second.step->dst, sc.dst[1], sc);
      break;
    }
    case BlockOp::Tex: {
      View c = tex_coord(in, st.aux, sc);
      if (textures.stage_state(static_cast<uint32_t>(st.aux)).projected) c = projected<D>(c, sc);
      sample(textures, st.aux, c, nullptr, n, d0);
      store<D>(st.dst, d0, sc);
      break;
    }
    case BlockOp::TexCoord: {
      const View c = tex_coord(in, st.aux, sc);
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < L; ++l) d0.c[k][l] = num::legacy_saturate<D>(c.c[k][l]);
      std::fill(std::begin(d0.c[3]), std::end(d0.c[3]), 1.0f);
      store<D>(st.dst, d0, sc);
      break;
    }
    case BlockOp::TexKill:
      kill_lanes<D>(p.ps11_13 ? tex_coord(in, st.aux, sc) : fetch<D>(im, b, 0, 0, sc),
                    p.ps1x ? 3 : 4, n, out);
      break;
    case BlockOp::TexLd14: {
      View c = fetch<D>(im, b, 0, 0, sc);
      c.c[3] = sc.zero;
      sample(textures, st.aux, c, nullptr, n, d0);
      store<D>(st.dst, d0, sc);
      break;
    }
    case BlockOp::TexCrd: {
      const View c = fetch<D>(im, b, 0, 0, sc);
      for (int k = 0; k < 4; ++k) std::memcpy(d0.c[k], c.c[k], sizeof(Lanes));
      store<D>(st.dst, d0, sc);
      break;
    }
    case BlockOp::TexLd:
      sample(textures, st.aux, fetch<D>(im, b, 0, 0, sc), nullptr, n, d0);
      store<D>(st.dst, d0, sc);
      break;
    case BlockOp::TexLdP:
      sample(textures, st.aux, projected<D>(fetch<D>(im, b, 0, 0, sc), sc), nullptr, n, d0);
      store<D>(st.dst, d0, sc);
      break;
    case BlockOp::TexLdB: {
      const View c = fetch<D>(im, b, 0, 0, sc);
      sample(textures, st.aux, c, c.c[3], n, d0);
      store<D>(st.dst, d0, sc);
      break;
    }
    case BlockOp::Phase:
      for (int r = 0; r < 6; ++r)
        std::fill(std::begin(sc.reg[vm::kTempBase + r].c[3]),
                  std::end(sc.reg[vm::kTempBase + r].c[3]), 0.0f);
      break;
    }
  }
  out.color = sc.reg[im.out_slot];
}

} // namespace

void PixelBlockVM::run(const PixelBlockInput& in, const TextureUnit& textures,
                       PixelBlockOutput& out, Scratch& sc) const {
  if (impl_->p.flush)
    run_steps<Denormals::Flush>(*impl_, in, textures, out, sc);
  else
    run_steps<Denormals::Keep>(*impl_, in, textures, out, sc);
}

void TextureUnit::sample_block(uint32_t stage, const float* const coord[4], const float* bias,
                               int n, Lanes out[4]) const {
  for (int l = 0; l < n; ++l) {
    const Vec4 r =
        sample(stage, {coord[0][l], coord[1][l], coord[2][l], coord[3][l]}, bias ? bias[l] : 0.0f);
    for (int c = 0; c < 4; ++c) out[c][l] = r[c];
  }
}

} // namespace tierlift::cpu
