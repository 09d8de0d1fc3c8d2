// Texture instructions: ps_1_1–1_3 texture-address instructions (docs/d3d9-rules.md §5.5),
// ps_1_4 texld/texcrd/texkill/texdepth (§5.6) and ps_2_0 texld/texldp/texldb/texkill
// (§5.7). Every sample goes through the TextureUnit; StageState supplies bump matrices
// and the projected flag. Each executor exists once per denormal mode (NUMERICS.md rule 13),
// dispatched through an OpcodeTable (the VM's one dispatch style, vm_internal.h).
#include "tierlift/ir/numerics.h"
#include "vm_internal.h"

namespace tierlift::cpu::vm {

namespace num = ir::numerics;
using ir::Opcode;
using num::Denormals;

namespace {

// TC(m): the interpolated texture coordinate set m.
Vec4 tc(const Invocation& inv, int32_t m) {
  if (!inv.pin || m < 0 || m >= 8) return {0, 0, 0, 0};
  return inv.pin->tex[static_cast<size_t>(m)];
}

Vec4 sample(const Invocation& inv, int32_t stage, const Vec4& coord, float bias = 0.0f) {
  if (!inv.tex || stage < 0) return {0, 0, 0, 1}; // unbound: opaque black (§10.6)
  return inv.tex->sample(static_cast<uint32_t>(stage), coord, bias);
}

StageState stage_state(const Invocation& inv, int32_t stage) {
  if (!inv.tex || stage < 0) return {};
  return inv.tex->stage_state(static_cast<uint32_t>(stage));
}

// D3DTTFF_PROJECTED (ps_1_1–1_3 tex, texbem): divide by the last coordinate, w (as DXVK).
template <Denormals D> Vec4 projected(Vec4 c, const StageState& ss) {
  if (!ss.projected) return c;
  float w = c[3];
  return {num::legacy_div<D>(c[0], w), num::legacy_div<D>(c[1], w), num::legacy_div<D>(c[2], w),
          1.0f};
}

template <Denormals D> float dot3(const Vec4& a, const Vec4& b) {
  return num::legacy_dp3<D>(a.data(), b.data());
}
Vec4 splat(float x) {
  return {x, x, x, x};
}

void discard(Invocation& inv) {
  if (inv.pout) inv.pout->discarded = true;
  // Nothing a discarded pixel computes afterwards is visible, except in a quad: there it runs on
  // as a helper lane, whose values its neighbours' dsx/dsy still read (NUMERICS.md rule F9).
  if (!inv.in_quad) inv.stop = true;
}

void set_depth(Invocation& inv, float z) {
  if (inv.pout) inv.pout->depth = z;
}

// --- ps_1_1 .. ps_1_3 ----------------------------------------------------------------

template <Denormals D> void ex_tex(const Step& s, Invocation& inv) {
  Vec4 c = projected<D>(tc(inv, s.aux), stage_state(inv, s.aux));
  store(s.dst, sample(inv, s.aux, c), inv);
}

// texcoord: (sat x, sat y, sat z, 1); no texture is read.
template <Denormals D> void ex_texcoord(const Step& s, Invocation& inv) {
  Vec4 c = tc(inv, s.aux);
  store(s.dst,
        {num::legacy_saturate<D>(c[0]), num::legacy_saturate<D>(c[1]),
         num::legacy_saturate<D>(c[2]), 1.0f},
        inv);
}

// texkill: ps_1_1–1_3 test TC(m).xyz; ps_1_4 the register's xyz; ps_2_0 all four.
// A predicated texkill ("(p0) texkill r0") tests component i only where p0's component i
// holds, as a predicated write writes it (NUMERICS.md F3): exec_predicated narrows the mask,
// which is 0xF otherwise.
template <Denormals D> void ex_texkill(const Step& s, Invocation& inv) {
  const Prepared& p = *inv.prog;
  Vec4 v = p.ps11_13 ? tc(inv, s.aux) : fetch(s.src[0], inv);
  int n = p.ps1x ? 3 : 4;
  for (int i = 0; i < n; ++i)
    if ((s.dst.mask >> i & 1) && num::dz<D>(v[i]) < 0.0f) return discard(inv);
}

// texbem/texbeml: offset TC(m) by stage m's 2×2 matrix times t(n).rg, then sample.
template <Denormals D>
Vec4 bump_sample(const Step& s, Invocation& inv, const Vec4& tn, const StageState& ss) {
  Vec4 c = projected<D>(tc(inv, s.aux), ss);
  const auto& m = ss.bumpenv_mat; // M00, M01, M10, M11
  const num::FloatArith<D> a;
  float u = num::rule::bump_offset(a, c[0], m[0], tn[0], m[2], tn[1]);
  float v = num::rule::bump_offset(a, c[1], m[1], tn[0], m[3], tn[1]);
  return sample(inv, s.aux, {u, v, c[2], c[3]});
}

template <Denormals D> void ex_texbem(const Step& s, Invocation& inv) {
  StageState ss = stage_state(inv, s.aux);
  store(s.dst, bump_sample<D>(s, inv, fetch(s.src[0], inv), ss), inv);
}

// texbeml: the sample times the luminance t(n).b·LSCALE + LOFFSET, not clamped (the
// docs' formula and Wine; DXVK clamps it to [0,1]).
template <Denormals D> void ex_texbeml(const Step& s, Invocation& inv) {
  StageState ss = stage_state(inv, s.aux);
  Vec4 tn = fetch(s.src[0], inv);
  Vec4 r = bump_sample<D>(s, inv, tn, ss);
  float l =
      num::rule::bump_luminance(num::FloatArith<D>{}, tn[2], ss.bumpenv_lscale, ss.bumpenv_loffset);
  for (float& x : r) x = num::legacy_mul<D>(x, l);
  store(s.dst, r, inv);
}

template <Denormals D> void ex_texreg2ar(const Step& s, Invocation& inv) {
  Vec4 n = fetch(s.src[0], inv);
  store(s.dst, sample(inv, s.aux, {n[3], n[0], 0, 0}), inv);
}
template <Denormals D> void ex_texreg2gb(const Step& s, Invocation& inv) {
  Vec4 n = fetch(s.src[0], inv);
  store(s.dst, sample(inv, s.aux, {n[1], n[2], 0, 0}), inv);
}
template <Denormals D> void ex_texreg2rgb(const Step& s, Invocation& inv) {
  Vec4 n = fetch(s.src[0], inv);
  store(s.dst, sample(inv, s.aux, {n[0], n[1], n[2], 0}), inv);
}

// Pads compute one row of the matrix product and write nothing (as DXVK).
template <Denormals D> void ex_pad(const Step& s, Invocation& inv) {
  inv.pad[s.pad_row] = dot3<D>(tc(inv, s.aux), fetch(s.src[0], inv));
}

template <Denormals D> void ex_texm3x2tex(const Step& s, Invocation& inv) {
  float v = dot3<D>(tc(inv, s.aux), fetch(s.src[0], inv));
  store(s.dst, sample(inv, s.aux, {inv.pad[0], v, 0, 0}), inv);
}

template <Denormals D> void ex_texm3x2depth(const Step& s, Invocation& inv) {
  float w = dot3<D>(tc(inv, s.aux), fetch(s.src[0], inv));
  set_depth(inv, num::legacy_depth_ratio<D>(inv.pad[0], w));
}

template <Denormals D> float third_row(const Step& s, Invocation& inv) {
  return dot3<D>(tc(inv, s.aux), fetch(s.src[0], inv));
}

template <Denormals D> void ex_texm3x3(const Step& s, Invocation& inv) {
  float w = third_row<D>(s, inv);
  store(s.dst, {inv.pad[0], inv.pad[1], w, 1.0f}, inv);
}

template <Denormals D> void ex_texm3x3tex(const Step& s, Invocation& inv) {
  float w = third_row<D>(s, inv);
  store(s.dst, sample(inv, s.aux, {inv.pad[0], inv.pad[1], w, 0}), inv);
}

template <Denormals D>
void reflect_and_sample(const Step& s, Invocation& inv, float w, num::Vec3f eye) {
  num::Vec3f r = num::legacy_reflect<D>({inv.pad[0], inv.pad[1], w}, eye);
  store(s.dst, sample(inv, s.aux, {r.x, r.y, r.z, 0}), inv);
}

template <Denormals D> void ex_texm3x3spec(const Step& s, Invocation& inv) {
  float w = third_row<D>(s, inv);
  Vec4 e = fetch(s.src[1], inv);
  reflect_and_sample<D>(s, inv, w, {e[0], e[1], e[2]});
}

// vspec: the eye vector is the w of the three coordinate sets m, m+1, m+2.
template <Denormals D> void ex_texm3x3vspec(const Step& s, Invocation& inv) {
  float w = third_row<D>(s, inv);
  num::Vec3f e{tc(inv, s.aux - 2)[3], tc(inv, s.aux - 1)[3], tc(inv, s.aux)[3]};
  reflect_and_sample<D>(s, inv, w, e);
}

template <Denormals D> void ex_texdp3(const Step& s, Invocation& inv) {
  store(s.dst, splat(dot3<D>(tc(inv, s.aux), fetch(s.src[0], inv))), inv);
}

template <Denormals D> void ex_texdp3tex(const Step& s, Invocation& inv) {
  float u = dot3<D>(tc(inv, s.aux), fetch(s.src[0], inv));
  store(s.dst, sample(inv, s.aux, {u, 0, 0, 0}), inv);
}

// --- ps_1_4 ----------------------------------------------------------------------------

// texld rM, src: samples stage M at src.xyz (after _dz/_dw and the .xyz/.xyw selector).
template <Denormals D> void ex_texld14(const Step& s, Invocation& inv) {
  Vec4 c = fetch(s.src[0], inv);
  store(s.dst, sample(inv, s.aux, {c[0], c[1], c[2], 0}), inv);
}

// texcrd: the coordinates themselves, not saturated.
template <Denormals D> void ex_texcrd(const Step& s, Invocation& inv) {
  store(s.dst, fetch(s.src[0], inv), inv);
}

template <Denormals D> void ex_texdepth(const Step& s, Invocation& inv) {
  Vec4 r5 = fetch(s.src[0], inv);
  set_depth(inv, num::legacy_depth_ratio<D>(r5[0], r5[1]));
}

// --- ps_2_0 ----------------------------------------------------------------------------

// --- ps_2_0+ reads with a level of detail (NUMERICS.md M4, M5) ------------------------
//
// At a quad step (ShaderVM::enable_lod_quads: a stage holds a mip chain read by lod) texld,
// texldp and texldb take the gradients of their coordinate across the quad as lavapipe does:
// the differences top-right − top-left and bottom-left − top-left, one pair for the whole
// quad. texldb's bias, texldl's lod and texldd's gradients are each pixel's own (measured:
// lavapipe evaluates those per pixel). Alone (no quad) the pixel is its own neighbour: zero
// gradients. A stage of one level ignores all of it.

template <Denormals D> Vec4 projected_coord(const Vec4& c) {
  auto div = num::legacy_div<D>;
  const float w = c[3];
  return {div(c[0], w), div(c[1], w), div(c[2], w), 1.0f};
}

// The coarse gradients of the quad's coordinates `lane[0..3]` (already projected for texldp).
template <Denormals D> void quad_gradients(const Vec4* lane, pass::LodInput& in) {
  auto sub = num::legacy_sub<D>;
  in.dudx = sub(lane[1][0], lane[0][0]);
  in.dvdx = sub(lane[1][1], lane[0][1]);
  in.dudy = sub(lane[2][0], lane[0][0]);
  in.dvdy = sub(lane[2][1], lane[0][1]);
}

Vec4 sample_lod(const Invocation& inv, int32_t stage, const Vec4& coord, const pass::LodInput& in) {
  if (!inv.tex || stage < 0) return {0, 0, 0, 1}; // unbound: opaque black (§10.6)
  return inv.tex->sample_lod(static_cast<uint32_t>(stage), coord, in);
}

template <Denormals D> void ex_texld(const Step& s, Invocation& inv) {
  const Vec4 c = fetch(s.src[0], inv);
  pass::LodInput in;
  if (inv.quad) quad_gradients<D>(inv.quad, in);
  store(s.dst, sample_lod(inv, s.aux, c, in), inv);
}

// texldp: xyz / w; the coordinate handed on has w = 1 (the gradients are the projected ones).
template <Denormals D> void ex_texldp(const Step& s, Invocation& inv) {
  const Vec4 c = projected_coord<D>(fetch(s.src[0], inv));
  pass::LodInput in;
  if (inv.quad) {
    const Vec4 lanes[4] = {projected_coord<D>(inv.quad[0]), projected_coord<D>(inv.quad[1]),
                           projected_coord<D>(inv.quad[2]), projected_coord<D>(inv.quad[3])};
    quad_gradients<D>(lanes, in);
  }
  store(s.dst, sample_lod(inv, s.aux, c, in), inv);
}

// texldd dst, coord, s#, ddx, ddy: the gradients given choose the level (rule F10).
template <Denormals D> void ex_texldd(const Step& s, Invocation& inv) {
  const Vec4 ddx = fetch(s.src[2], inv), ddy = fetch(s.src[3], inv);
  pass::LodInput in;
  in.dudx = ddx[0], in.dvdx = ddx[1], in.dudy = ddy[0], in.dvdy = ddy[1];
  store(s.dst, sample_lod(inv, s.aux, fetch(s.src[0], inv), in), inv);
}

// texldb: the lod of the quad's gradients plus src.w.
template <Denormals D> void ex_texldb(const Step& s, Invocation& inv) {
  const Vec4 c = fetch(s.src[0], inv);
  pass::LodInput in;
  in.has_bias = true;
  in.bias = c[3];
  if (inv.quad) quad_gradients<D>(inv.quad, in);
  store(s.dst, sample_lod(inv, s.aux, c, in), inv);
}

// texldl: the level of detail is src.w, no bias (rule F11).
template <Denormals D> void ex_texldl(const Step& s, Invocation& inv) {
  const Vec4 c = fetch(s.src[0], inv);
  pass::LodInput in;
  in.explicit_lod = true;
  in.lod = c[3];
  store(s.dst, sample_lod(inv, s.aux, c, in), inv);
}

} // namespace

namespace {

template <Denormals D> constexpr OpcodeTable<ExecFn> texture_table() {
  const std::pair<Opcode, ExecFn> rows[] = {{Opcode::Tex, ex_tex<D>},
                                            {Opcode::TexCoord, ex_texcoord<D>},
                                            {Opcode::TexKill, ex_texkill<D>},
                                            {Opcode::TexBem, ex_texbem<D>},
                                            {Opcode::TexBemL, ex_texbeml<D>},
                                            {Opcode::TexReg2Ar, ex_texreg2ar<D>},
                                            {Opcode::TexReg2Gb, ex_texreg2gb<D>},
                                            {Opcode::TexReg2Rgb, ex_texreg2rgb<D>},
                                            {Opcode::TexM3x2Pad, ex_pad<D>},
                                            {Opcode::TexM3x3Pad, ex_pad<D>},
                                            {Opcode::TexM3x2Tex, ex_texm3x2tex<D>},
                                            {Opcode::TexM3x2Depth, ex_texm3x2depth<D>},
                                            {Opcode::TexM3x3, ex_texm3x3<D>},
                                            {Opcode::TexM3x3Tex, ex_texm3x3tex<D>},
                                            {Opcode::TexM3x3Spec, ex_texm3x3spec<D>},
                                            {Opcode::TexM3x3VSpec, ex_texm3x3vspec<D>},
                                            {Opcode::TexDp3, ex_texdp3<D>},
                                            {Opcode::TexDp3Tex, ex_texdp3tex<D>},
                                            {Opcode::TexLd14, ex_texld14<D>},
                                            {Opcode::TexCrd, ex_texcrd<D>},
                                            {Opcode::TexDepth, ex_texdepth<D>},
                                            {Opcode::TexLd, ex_texld<D>},
                                            {Opcode::TexLdP, ex_texldp<D>},
                                            {Opcode::TexLdB, ex_texldb<D>},
                                            {Opcode::TexLdD, ex_texldd<D>},
                                            {Opcode::TexLdL, ex_texldl<D>}};
  return OpcodeTable<ExecFn>(rows);
}
constexpr OpcodeTable<ExecFn> kTextureKeep = texture_table<Denormals::Keep>();
constexpr OpcodeTable<ExecFn> kTextureFlush = texture_table<Denormals::Flush>();

} // namespace

ExecFn texture_exec(Opcode op, bool flush_denormals) {
  return (flush_denormals ? kTextureFlush : kTextureKeep)[op];
}

} // namespace tierlift::cpu::vm
