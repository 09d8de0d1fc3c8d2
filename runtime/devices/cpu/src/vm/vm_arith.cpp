// The arithmetic instructions: one compute function per opcode, dispatched through an
// OpcodeTable (the VM's one dispatch style, vm_internal.h). Each one only computes; the executor
// fetches every source first and stores afterwards, which gives matrix macros and co-issued pairs
// their read-before-write semantics (docs/d3d9-rules.md §4.6, §5.1). Every numeric rule comes from
// ir/numeric_rules.h (through ir/numerics.h); each compute function exists twice, once per denormal
// mode (NUMERICS.md rule 13), and the table of the program's mode is chosen at preparation.
#include <array>
#include <cmath>
#include <type_traits>

#include "tierlift/ir/numerics.h"
#include "tierlift/rounding/rounding.h"
#include "vm_internal.h"

namespace tierlift::cpu::vm {

namespace num = ir::numerics;
using ir::Opcode;
using num::Denormals;

namespace {

// Scalar operands read the 4th swizzle slot (docs/d3d9-rules.md §4.3).
inline float sc(const Vec4& v) {
  return v[3];
}
inline Vec4 splat(float x) {
  return {x, x, x, x};
}

template <typename F> inline Vec4 each(const Vec4& a, F f) {
  return {f(a[0]), f(a[1]), f(a[2]), f(a[3])};
}
template <typename F> inline Vec4 each(const Vec4& a, const Vec4& b, F f) {
  return {f(a[0], b[0]), f(a[1], b[1]), f(a[2], b[2]), f(a[3], b[3])};
}
template <typename F> inline Vec4 each(const Vec4& a, const Vec4& b, const Vec4& c, F f) {
  return {f(a[0], b[0], c[0]), f(a[1], b[1], c[1]), f(a[2], b[2], c[2]), f(a[3], b[3], c[3])};
}

// The back end of the rules that take exp2 or log2 (exp, log, pow, lit, expp, logp): flushing
// denormals is Rounding::Llvmpipe, whose exp2 and log2 are lavapipe's polynomials; Exact's are
// the C library's (rule 40).
template <Denormals D>
using ExpLogArith =
    std::conditional_t<D == Denormals::Keep, num::FloatArith<D>, rounding::LlvmpipeArith<D>>;

// Every compute function has the same signature; most use only some of the parameters.
#define VM_OP(name)                                                                                \
  template <Denormals D>                                                                           \
  void name([[maybe_unused]] const Step& st, [[maybe_unused]] const Vec4* s,                       \
            [[maybe_unused]] Vec4& d, [[maybe_unused]] Invocation& inv)

VM_OP(op_nop) {}
VM_OP(op_mov) {
  d = s[0];
}
VM_OP(op_add) {
  d = each(s[0], s[1], num::legacy_add<D>);
}
VM_OP(op_sub) {
  d = each(s[0], s[1], num::legacy_sub<D>);
}
VM_OP(op_mul) {
  d = each(s[0], s[1], num::legacy_mul<D>);
}
VM_OP(op_mad) {
  d = each(s[0], s[1], s[2], num::legacy_mad<D>);
}
VM_OP(op_dp3) {
  d = splat(num::legacy_dp3<D>(s[0].data(), s[1].data()));
}
VM_OP(op_dp4) {
  d = splat(num::legacy_dp4<D>(s[0].data(), s[1].data()));
}
VM_OP(op_min) {
  d = each(s[0], s[1], num::legacy_min<D>);
}
VM_OP(op_max) {
  d = each(s[0], s[1], num::legacy_max<D>);
}
VM_OP(op_slt) {
  d = each(s[0], s[1], num::legacy_slt<D>);
}
VM_OP(op_sge) {
  d = each(s[0], s[1], num::legacy_sge<D>);
}
VM_OP(op_rcp) {
  d = splat(num::legacy_rcp<D>(sc(s[0])));
}
VM_OP(op_rsq) {
  d = splat(num::legacy_rsq<D>(sc(s[0])));
}
VM_OP(op_exp) {
  d = splat(num::rule::exp(ExpLogArith<D>{}, sc(s[0])));
}
VM_OP(op_log) {
  d = splat(num::rule::log(ExpLogArith<D>{}, sc(s[0])));
}
VM_OP(op_pow) {
  d = splat(num::rule::pow(ExpLogArith<D>{}, sc(s[0]), sc(s[1])));
}
VM_OP(op_abs) {
  d = each(s[0], [](float a) { return std::fabs(a); });
}
VM_OP(op_frc) {
  d = each(s[0], num::legacy_frc<D>);
}
VM_OP(op_sgn) {
  d = each(s[0], num::legacy_sgn<D>);
}
VM_OP(op_lrp) {
  d = each(s[0], s[1], s[2], num::legacy_lrp<D>);
}
VM_OP(op_cmp) {
  d = each(s[0], s[1], s[2], num::legacy_cmp<D>);
}

// cnd: ps_1_1–1_3 compare r0.a (the validator requires src0 = r0.a, a replicate swizzle,
// so every component of s[0] already holds it); ps_1_4 compares per component.
VM_OP(op_cnd) {
  d = each(s[0], s[1], s[2], num::legacy_cnd<D>);
}

VM_OP(op_lit) {
  num::LitResult r = num::rule::lit(ExpLogArith<D>{}, s[0][0], s[0][1], s[0][3]);
  d = {r.x, r.y, r.z, r.w};
}

VM_OP(op_dst) {
  d = {1.0f, num::legacy_mul<D>(s[0][1], s[1][1]), s[0][2], s[1][3]};
}

VM_OP(op_crs) {
  const Vec4 &a = s[0], &b = s[1];
  auto cross = [&](int i, int j) {
    return num::rule::cross_component(num::FloatArith<D>{}, a[i], b[j], a[j], b[i]);
  };
  d = {cross(1, 2), cross(2, 0), cross(0, 1), 0.0f};
}

VM_OP(op_nrm) {
  float f = num::legacy_nrm_scale<D>(num::legacy_dp3<D>(s[0].data(), s[0].data()));
  d = each(s[0], [f](float a) { return num::legacy_mul<D>(a, f); });
}

// sincos (both forms: 2.0's constants are not read): d.x = cos, d.y = sin; the mask was
// limited to .xy at preparation. Flushing denormals is Rounding::Llvmpipe, whose sine and
// cosine are lavapipe's polynomial; Exact's are the correctly rounded ones (rule 39).
VM_OP(op_sincos) {
  const float a = sc(s[0]);
  if constexpr (D == Denormals::Keep)
    d = {rounding::cos_exact(a), rounding::sin_exact(a), 0.0f, 0.0f};
  else
    d = {rounding::cos_llvmpipe(a), rounding::sin_llvmpipe(a), 0.0f, 0.0f};
}

VM_OP(op_dp2add) {
  d = splat(num::rule::dp2add(num::FloatArith<D>{}, s[0].data(), s[1].data(), sc(s[2])));
}

// expp: vs_1_1 is the D3D8 vector macro (2^floor(v), v − floor(v), 2^v, 1); vs_2_0 is
// the scalar 2^v (computed here at full precision).
VM_OP(op_expp) {
  float v = sc(s[0]);
  if (!inv.prog->vs11) {
    d = splat(num::rule::exp(ExpLogArith<D>{}, v));
    return;
  }
  const auto r = num::rule::expp_partial(ExpLogArith<D>{}, v);
  d = {r.x, r.y, r.z, r.w};
}

// logp: the D3D9 docs define it, in every version, as the scalar log of |v|.
VM_OP(op_logp) {
  d = splat(num::rule::log(ExpLogArith<D>{}, sc(s[0])));
}

// Matrix macros: d[i] = dot(src0, row i); rows were fetched into s[1..rows].
VM_OP(op_m4) {
  d = {0, 0, 0, 0};
  for (int i = 0; i < st.rows; ++i) d[i] = num::legacy_dp4<D>(s[0].data(), s[1 + i].data());
}
VM_OP(op_m3) {
  d = {0, 0, 0, 0};
  for (int i = 0; i < st.rows; ++i) d[i] = num::legacy_dp3<D>(s[0].data(), s[1 + i].data());
}

// bem (ps_1_4): the bump matrix of the stage named by the destination register.
VM_OP(op_bem) {
  StageState ss = inv.tex ? inv.tex->stage_state(static_cast<uint32_t>(st.aux)) : StageState{};
  const auto& m = ss.bumpenv_mat; // M00, M01, M10, M11
  const num::FloatArith<D> a;
  d = {num::rule::bump_offset(a, s[0][0], m[0], s[1][0], m[2], s[1][1]),
       num::rule::bump_offset(a, s[0][1], m[1], s[1][0], m[3], s[1][1]), 0.0f, 0.0f};
}

// dsx/dsy (NUMERICS.md rule F8): fine differences inside the 2x2 quad, right minus left on
// the lane's own row, bottom minus top in its own column, as lavapipe's OpDPdxFine/OpDPdyFine.
// Alone (no quad) the pixel is its own neighbour.
VM_OP(op_dsx) {
  if (!inv.quad) {
    d = each(s[0], s[0], num::legacy_sub<D>);
    return;
  }
  const int row = inv.lane & 2;
  d = each(inv.quad[row + 1], inv.quad[row], num::legacy_sub<D>);
}
VM_OP(op_dsy) {
  if (!inv.quad) {
    d = each(s[0], s[0], num::legacy_sub<D>);
    return;
  }
  const int column = inv.lane & 1;
  d = each(inv.quad[column + 2], inv.quad[column], num::legacy_sub<D>);
}

#undef VM_OP

// Mova computes a mov: the conversion happens at the store (DstKind::AddrRound).
template <Denormals D> constexpr OpcodeTable<ComputeFn> compute_table() {
  const std::pair<Opcode, ComputeFn> rows[] = {
      {Opcode::Nop, op_nop<D>},   {Opcode::Mov, op_mov<D>},       {Opcode::Mova, op_mov<D>},
      {Opcode::Add, op_add<D>},   {Opcode::Sub, op_sub<D>},       {Opcode::Mad, op_mad<D>},
      {Opcode::Mul, op_mul<D>},   {Opcode::Rcp, op_rcp<D>},       {Opcode::Rsq, op_rsq<D>},
      {Opcode::Dp3, op_dp3<D>},   {Opcode::Dp4, op_dp4<D>},       {Opcode::Min, op_min<D>},
      {Opcode::Max, op_max<D>},   {Opcode::Slt, op_slt<D>},       {Opcode::Sge, op_sge<D>},
      {Opcode::Exp, op_exp<D>},   {Opcode::Log, op_log<D>},       {Opcode::Lit, op_lit<D>},
      {Opcode::Dst, op_dst<D>},   {Opcode::Lrp, op_lrp<D>},       {Opcode::Frc, op_frc<D>},
      {Opcode::M4x4, op_m4<D>},   {Opcode::M4x3, op_m4<D>},       {Opcode::M3x4, op_m3<D>},
      {Opcode::M3x3, op_m3<D>},   {Opcode::M3x2, op_m3<D>},       {Opcode::Pow, op_pow<D>},
      {Opcode::Crs, op_crs<D>},   {Opcode::Sgn, op_sgn<D>},       {Opcode::Abs, op_abs<D>},
      {Opcode::Nrm, op_nrm<D>},   {Opcode::SinCos, op_sincos<D>}, {Opcode::Expp, op_expp<D>},
      {Opcode::Logp, op_logp<D>}, {Opcode::Cnd, op_cnd<D>},       {Opcode::Cmp, op_cmp<D>},
      {Opcode::Bem, op_bem<D>},   {Opcode::Dp2Add, op_dp2add<D>}, {Opcode::SinCos3, op_sincos<D>},
      {Opcode::Dsx, op_dsx<D>},   {Opcode::Dsy, op_dsy<D>}};
  return OpcodeTable<ComputeFn>(rows);
}
constexpr OpcodeTable<ComputeFn> kComputeKeep = compute_table<Denormals::Keep>();
constexpr OpcodeTable<ComputeFn> kComputeFlush = compute_table<Denormals::Flush>();

// Fetches every source of one arithmetic step (matrix rows included) into s.
inline void fetch_all(const Step& st, Vec4* s, const Invocation& inv) {
  if (!st.rows) {
    for (int i = 0; i < st.nsrc; ++i) s[i] = fetch(st.src[i], inv);
    return;
  }
  // Matrix macro: src0, then consecutive registers from the matrix operand (src1).
  s[0] = fetch(st.src[0], inv);
  const auto& defs = inv.prog->const_defs;
  for (int i = 0; i < st.rows; ++i) {
    SrcDesc row = st.src[1];
    row.slot = static_cast<uint16_t>(row.slot + i);
    if (row.kind == SrcKind::Const)
      row.def = row.slot < defs.size() && defs[row.slot] ? &*defs[row.slot] : nullptr;
    s[1 + i] = fetch(row, inv);
  }
}

} // namespace

ComputeFn arith_compute(Opcode op, bool flush_denormals) {
  return (flush_denormals ? kComputeFlush : kComputeKeep)[op];
}

void exec_arith(const Step& st, Invocation& inv) {
  Vec4 s[5];
  Vec4 d;
  fetch_all(st, s, inv);
  st.compute(st, s, d, inv);
  store(st.dst, d, inv);
}

// A co-issued pair (ps_1_x "+"): both halves read before either writes.
void exec_arith_pair(const Step& st, Invocation& inv) {
  const Step& second = (&st)[1];
  Vec4 s1[5], s2[5];
  Vec4 d1, d2;
  fetch_all(st, s1, inv);
  fetch_all(second, s2, inv);
  st.compute(st, s1, d1, inv);
  second.compute(second, s2, d2, inv);
  store(st.dst, d1, inv);
  store(second.dst, d2, inv);
  ++inv.pc; // the second half has run
}

} // namespace tierlift::cpu::vm
