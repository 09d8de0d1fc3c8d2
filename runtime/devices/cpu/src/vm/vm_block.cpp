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

#include "tierlift/cpu/cpu_features.h"
#include "tierlift/cpu/pixel_block.h"
#include "tierlift/ir/numerics.h"
#include "vm_block_internal.h"
#include "vm_block_store.h"

namespace tierlift::cpu {

namespace num = ir::numerics;
using ir::Opcode;
using num::Denormals;
using namespace block;

namespace {

using Impl = PixelBlockVM::Impl;
using Scratch = PixelBlockVM::Scratch;

// The lanes a register source reads: the register, or the block's coordinates in place.
TL_INLINE const LaneVec4& reg(const BlockSrc& s, const Scratch& sc) {
  return s.input ? sc.in->tex[s.slot - vm::kTexBase] : sc.reg[s.slot];
}

template <Denormals D>
TL_INLINE void fetch(const Impl& im, const BlockStep& b, int k, int half, Scratch& sc, View& v) {
  const BlockSrc& s = b.src[static_cast<size_t>(k)];
  switch (s.way) {
  case SrcWay::Folded:
    for (int c = 0; c < 4; ++c) v.c[c] = im.folded[static_cast<size_t>(s.folded)].c[c];
    return;
  case SrcWay::Reg:
    for (int c = 0; c < 4; ++c) v.c[c] = reg(s, sc).c[s.comp[c]];
    return;
  case SrcWay::Neg: {
    LaneVec4& out = sc.src[half][k];
    for (int c = 0; c < 4; ++c) {
      const float* r = reg(s, sc).c[s.comp[c]];
      for (int l = 0; l < L; ++l) out.c[c][l] = -r[l];
      v.c[c] = out.c[c];
    }
    return;
  }
  case SrcWay::General: {
    LaneVec4& out = sc.src[half][k];
    const LaneVec4& r = reg(s, sc);
    const vm::SrcDesc& d = b.step->src[static_cast<size_t>(k)];
    for (int l = 0; l < L; ++l) {
      Vec4 x = vm::modify_src<D>(d, {r.c[0][l], r.c[1][l], r.c[2][l], r.c[3][l]});
      for (int c = 0; c < 4; ++c) out.c[c][l] = x[c];
    }
    for (int c = 0; c < 4; ++c) v.c[c] = out.c[c];
    return;
  }
  }
}

// One source as a value (the texture and kill steps). compute() fills its array in place
// instead: a View returned and then copied costs a stalled store-to-load forward per source
// (the copy reads 16 bytes the fill wrote 8 at a time).
template <Denormals D>
TL_INLINE View fetch(const Impl& im, const BlockStep& b, int k, int half, Scratch& sc) {
  View v;
  fetch<D>(im, b, k, half, sc, v);
  return v;
}

// d[c][l] = f(a[c][l], …) for the components in `mask` (the only ones the store keeps) and
// every lane: one rule function per lane. d may be the destination register itself (a
// BlockStep::direct step), so a source may share memory with it, but only lane for lane (the
// plan rules out the rest): ivdep tells the vectoriser so, where __restrict would be false.
// "unroll 1" keeps GCC from unrolling the lane loop completely before the loop vectoriser
// sees it: the vectoriser if-converts the rule functions' selects, the straight-line
// vectoriser after unrolling cannot.
template <typename F> TL_INLINE void lanes1(LaneVec4& d, int mask, const View& a, F f) {
  for (int c = 0; c < 4; ++c) {
    if (!(mask & (1 << c))) continue;
    float* o = d.c[c];
    const float* x = a.c[c];
#pragma GCC ivdep
#pragma GCC unroll 1
    for (int l = 0; l < L; ++l) o[l] = f(x[l]);
  }
}
template <typename F>
TL_INLINE void lanes2(LaneVec4& d, int mask, const View& a, const View& b, F f) {
  for (int c = 0; c < 4; ++c) {
    if (!(mask & (1 << c))) continue;
    float* o = d.c[c];
    const float *x = a.c[c], *y = b.c[c];
#pragma GCC ivdep
#pragma GCC unroll 1
    for (int l = 0; l < L; ++l) o[l] = f(x[l], y[l]);
  }
}
template <typename F>
TL_INLINE void lanes3(LaneVec4& d, int mask, const View& a, const View& b, const View& e, F f) {
  for (int c = 0; c < 4; ++c) {
    if (!(mask & (1 << c))) continue;
    float* o = d.c[c];
    const float *x = a.c[c], *y = b.c[c], *z = e.c[c];
#pragma GCC ivdep
#pragma GCC unroll 1
    for (int l = 0; l < L; ++l) o[l] = f(x[l], y[l], z[l]);
  }
}
// A dot product per lane, splatted to the components in `mask` (as the VM's splat). A lane's
// sources are read before its results are written.
template <typename F>
TL_INLINE void lanes_dot(LaneVec4& d, int mask, const View& a, const View& b, F dot) {
  for (int l = 0; l < L; ++l) {
    const float x[4] = {a.c[0][l], a.c[1][l], a.c[2][l], a.c[3][l]};
    const float y[4] = {b.c[0][l], b.c[1][l], b.c[2][l], b.c[3][l]};
    const float r = dot(x, y, l);
    for (int c = 0; c < 4; ++c)
      if (mask & (1 << c)) d.c[c][l] = r;
  }
}

// Every other arithmetic instruction: the VM's own compute function, lane by lane.
void compute_per_lane(const vm::Step& st, const View* s, int n, int mask, LaneVec4& d,
                      vm::Invocation& inv) {
  for (int l = 0; l < n; ++l) {
    Vec4 in[5];
    for (int k = 0; k < st.nsrc; ++k)
      in[k] = {s[k].c[0][l], s[k].c[1][l], s[k].c[2][l], s[k].c[3][l]};
    Vec4 r{0, 0, 0, 0};
    st.compute(st, in, r, inv);
    for (int c = 0; c < 4; ++c)
      if (mask & (1 << c)) d.c[c][l] = r[c];
  }
}

// Source k is a folded constant none of whose components in `mask` compares equal to zero
// (BlockSrc::nonzero): products with it test only the other factor.
TL_INLINE bool nonzero_factor(const BlockStep& b, int k, int mask) {
  const BlockSrc& s = b.src[static_cast<size_t>(k)];
  return s.way == SrcWay::Folded && (s.nonzero & mask) == mask;
}

// Source k is a folded constant whose components in `mask` are all ±0 (BlockSrc::zero): a
// product with it is +0 (rule 8), whatever the other factor holds.
TL_INLINE bool zero_factor(const BlockStep& b, int k, int mask) {
  const BlockSrc& s = b.src[static_cast<size_t>(k)];
  return s.way == SrcWay::Folded && (s.zero & mask) == mask;
}

// The VM's compute functions of the same opcodes (vm_arith.cpp) call the same rules with the
// same D; compute_per_lane calls the VM's own, taken from the table of the program's mode.
// Sources are fetched under D and the rules run under R: D, or FlushResults for a step
// whose sources hold no denormal (compute, below).
template <Denormals D, Denormals R>
TL_INLINE void compute_as(const Impl& im, const BlockStep& b, int half, int n, Scratch& sc,
                          LaneVec4& d, vm::Invocation& inv) {
  const vm::Step& st = *b.step;
  const int m = st.dst.mask;
  View s[4];
  for (int k = 0; k < st.nsrc; ++k) fetch<D>(im, b, k, half, sc, s[k]);
  switch (st.ins->op) {
  case Opcode::Mov: lanes1(d, m, s[0], [](float a) { return a; }); return;
  case Opcode::Add:
    lanes2(d, m, s[0], s[1], [](float a, float e) { return num::legacy_add<R>(a, e); });
    return;
  case Opcode::Sub:
    lanes2(d, m, s[0], s[1], [](float a, float e) { return num::legacy_sub<R>(a, e); });
    return;
  case Opcode::Mul:
    if (zero_factor(b, 1, m) || zero_factor(b, 0, m))
      lanes1(d, m, s[0], [](float) { return 0.0f; });
    else if (nonzero_factor(b, 1, m))
      lanes2(d, m, s[0], s[1], [](float a, float e) { return num::legacy_mul_y_nonzero<R>(a, e); });
    else if (nonzero_factor(b, 0, m))
      lanes2(d, m, s[0], s[1], [](float a, float e) { return num::legacy_mul_x_nonzero<R>(a, e); });
    else
      lanes2(d, m, s[0], s[1], [](float a, float e) { return num::legacy_mul<R>(a, e); });
    return;
  case Opcode::Mad:
    if (zero_factor(b, 1, m) || zero_factor(b, 0, m))
      lanes1(d, m, s[2], [](float f) { return num::legacy_add<R>(0.0f, f); });
    else if (nonzero_factor(b, 1, m))
      lanes3(d, m, s[0], s[1], s[2],
             [](float a, float e, float f) { return num::legacy_mad_y_nonzero<R>(a, e, f); });
    else if (nonzero_factor(b, 0, m))
      lanes3(d, m, s[0], s[1], s[2],
             [](float a, float e, float f) { return num::legacy_mad_x_nonzero<R>(a, e, f); });
    else
      lanes3(d, m, s[0], s[1], s[2],
             [](float a, float e, float f) { return num::legacy_mad<R>(a, e, f); });
    return;
  case Opcode::Min:
    lanes2(d, m, s[0], s[1], [](float a, float e) { return num::legacy_min<R>(a, e); });
    return;
  case Opcode::Max:
    lanes2(d, m, s[0], s[1], [](float a, float e) { return num::legacy_max<R>(a, e); });
    return;
  case Opcode::Slt:
    lanes2(d, m, s[0], s[1], [](float a, float e) { return num::legacy_slt<R>(a, e); });
    return;
  case Opcode::Sge:
    lanes2(d, m, s[0], s[1], [](float a, float e) { return num::legacy_sge<R>(a, e); });
    return;
  case Opcode::Lrp:
    lanes3(d, m, s[0], s[1], s[2],
           [](float a, float e, float f) { return num::legacy_lrp<R>(a, e, f); });
    return;
  case Opcode::Cmp:
    lanes3(d, m, s[0], s[1], s[2],
           [](float a, float e, float f) { return num::legacy_cmp<R>(a, e, f); });
    return;
  case Opcode::Cnd:
    lanes3(d, m, s[0], s[1], s[2],
           [](float a, float e, float f) { return num::legacy_cnd<R>(a, e, f); });
    return;
  case Opcode::Abs: lanes1(d, m, s[0], [](float a) { return std::fabs(a); }); return;
  case Opcode::Dp3:
    lanes_dot(d, m, s[0], s[1],
              [](const float* x, const float* y, int) { return num::legacy_dp3<R>(x, y); });
    return;
  case Opcode::Dp4:
    lanes_dot(d, m, s[0], s[1],
              [](const float* x, const float* y, int) { return num::legacy_dp4<R>(x, y); });
    return;
  case Opcode::Dp2Add: {
    const float* w = s[2].c[3]; // the scalar operand reads its 4th swizzle slot
    lanes_dot(d, m, s[0], s[1], [w](const float* x, const float* y, int l) {
      return num::legacy_add<R>(num::legacy_dp2<R>(x, y), w[l]);
    });
    return;
  }
  default: compute_per_lane(st, s, n, m, d, inv); return;
  }
}

// compute under D, with the operand flushes left out where BlockStep::clean says no source
// can hold a denormal (the same values: flushing a value that is not one changes nothing).
template <Denormals D>
TL_INLINE void compute(const Impl& im, const BlockStep& b, int half, int n, Scratch& sc,
                       LaneVec4& d, vm::Invocation& inv) {
  if constexpr (D == Denormals::Flush)
    if (b.clean) return compute_as<D, Denormals::FlushResults>(im, b, half, n, sc, d, inv);
  compute_as<D, D>(im, b, half, n, sc, d, inv);
}

template <Denormals D> TL_INLINE void store(const vm::DstDesc& d, const LaneVec4& v, Scratch& sc) {
  if (d.kind != vm::DstKind::Slot) return; // address registers never reach the block path
  store_lanes<D>(d, v, sc.reg[d.slot]);
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
TL_INLINE void run_steps_body(const Impl& im, const PixelBlockInput& in,
                              const TextureUnit& textures, PixelBlockOutput& out, Scratch& sc) {
  const vm::Prepared& p = im.p;
  const int n = std::clamp(in.count, 0, L);
  for (const auto& [slot, c] : im.zero_components)
    std::fill(std::begin(sc.reg[slot].c[c]), std::end(sc.reg[slot].c[c]), 0.0f);
  // The inputs as run_pixel sets them: colours saturated before ps_3_0; t# are the
  // coordinates except in ps_1_1–1_3, where texture instructions fill them.
  for (int i = 0; i < 2; ++i)
    if (im.color_reads & (1u << i))
      for (int c = 0; c < 4; ++c)
        for (int l = 0; l < L; ++l)
          sc.reg[vm::kInputBase + i].c[c][l] = p.saturate_colors
                                                   ? num::legacy_saturate<D>(in.color[i].c[c][l])
                                                   : in.color[i].c[c][l];
  sc.in = &in;
  for (int i = 0; i < vm::kTexCount; ++i)
    if (im.tex_copies & (1u << i)) sc.reg[vm::kTexBase + i] = in.tex[i];
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
      if (b.direct) {
        compute<D>(im, b, 0, n, sc, sc.reg[st.dst.slot], inv);
        break;
      }
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
      if (b.direct) {
        sample(textures, st.aux, c, nullptr, n, sc.reg[st.dst.slot]);
        break;
      }
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
      sample(textures, st.aux, fetch<D>(im, b, 0, 0, sc), nullptr, n,
             b.direct ? sc.reg[st.dst.slot] : d0);
      if (!b.direct) store<D>(st.dst, d0, sc);
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
  out.color = &sc.reg[im.out_slot];
}

// The steps built twice: for the baseline and for AVX2, chosen per run by what the CPU has.
// The lane loops then run eight floats a step instead of four; every operation is the same
// IEEE operation on the same values (no FMA: the build forbids contraction), so both builds
// compute the same bits.
template <Denormals D>
void run_steps(const Impl& im, const PixelBlockInput& in, const TextureUnit& textures,
               PixelBlockOutput& out, Scratch& sc) {
  run_steps_body<D>(im, in, textures, out, sc);
}

#if defined(__x86_64__) && defined(__GNUC__)
template <Denormals D>
[[gnu::target("avx2")]] void run_steps_avx2(const Impl& im, const PixelBlockInput& in,
                                            const TextureUnit& textures, PixelBlockOutput& out,
                                            Scratch& sc) {
  run_steps_body<D>(im, in, textures, out, sc);
}
#else
template <Denormals D>
void run_steps_avx2(const Impl& im, const PixelBlockInput& in, const TextureUnit& textures,
                    PixelBlockOutput& out, Scratch& sc) {
  run_steps_body<D>(im, in, textures, out, sc);
}
#endif

} // namespace

void PixelBlockVM::run(const PixelBlockInput& in, const TextureUnit& textures,
                       PixelBlockOutput& out, Scratch& sc) const {
  const bool wide = cpu_runs_avx2();
  if (impl_->p.flush)
    (wide ? run_steps_avx2<Denormals::Flush> : run_steps<Denormals::Flush>)(*impl_, in, textures,
                                                                            out, sc);
  else
    (wide ? run_steps_avx2<Denormals::Keep> : run_steps<Denormals::Keep>)(*impl_, in, textures, out,
                                                                          sc);
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
