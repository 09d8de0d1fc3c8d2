// Where Direct3D 9 and Vulkan leave the rounding to the implementation, what lavapipe (Mesa
// llvmpipe) does and what exact IEEE arithmetic does, side by side: one place for the
// arithmetic model the CPU device follows under ir::Rounding::Llvmpipe (the default, which
// makes it agree with the Vulkan device bit for bit) and the exact rules it follows under
// ir::Rounding::Exact and that img::quantize applies. Each lavapipe rule was measured
// against lavapipe (Mesa 22.3, x86-64); NUMERICS.md gives the rule numbers and the evidence.
//
//   rule                      lavapipe                                 exact
//   RGBA8 store               fl32(v·255), ties to even (unorm8_       v·255 in double, ties up
//                             llvmpipe)                                (unorm8_nearest)
//   RGBA16F store             toward zero, ±65504 cap (half_toward_    nearest even, overflow to
//                             zero)                                    inf (half_nearest_even)
//   denormals                 flushed in and out of every operation    kept
//                             of setup, interpolation and filtering
//                             (flush)
//   attribute interpolation   float planes a0 + dadx·x + dady·y with   exact barycentrics in
//                             FMA, times 1/w, flushed (plane_at,       double (cpu/src/draw)
//                             perspective_at)
//   bilinear weights          α = frac(fl32(u·N) − ½) in float, clamp   α = frac(u·N − ½) in
//                             on the coordinate (linear_axis)          double (cpu texture.h)
//   bilinear lerp             v0 + α·(v1 − v0) as one FMA, flushed     weights in double
//                             (lerp)
//   sin, cos (sincos)         Cody-Waite reduction by π/4 and a        sin/cos in double,
//                             degree 7/8 polynomial in float with      rounded once
//                             FMAs (sin_llvmpipe, cos_llvmpipe)        (sin_exact, cos_exact)
//   exp2, log2 (exp, log,     exponent split and a degree-5 minimax    the C library's exp2f,
//   pow, lit, expp, logp)     polynomial; mantissa y = (m−1)/(m+1)     log2f (FloatArith<Keep>)
//                             and a degree-4 polynomial in y², FMAs
//                             (exp2_llvmpipe, log2_llvmpipe, LlvmpipeArith)
//   sRGB decode / encode      the exact rule on both devices: neither  IEC 61966-2-1 in double
//                             uses a Vulkan sRGB format (srgb_*)       (srgb_decode_levels, …)
//
// The analytic model (runtime/devices/analytic) keeps its own copies on purpose: an oracle
// that shared this code with the devices would agree with them by construction.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "tierlift/ir/numerics.h"

namespace tierlift::rounding {

// ---- RGBA8 stores ----------------------------------------------------------------------

// Exact: NaN stores 0 (as Vulkan and D3D conversions do); otherwise clamp to [0, 1], then
// the nearest of the 255 steps with ties up, as k/255 in float. value·255 is exact in double
// (24 + 8 bits), so a tie is decided on the float's true value.
float unorm8_nearest(float value);

// lavapipe, when it writes a colour attachment: NaN and values ≤ 0 give 0, values ≥ 1 give
// 255, otherwise the float product fl32(value·255) rounded to the nearest integer with ties
// to even (llvmpipe multiplies by 255 in float and converts with cvtps2dq, whose default
// rounding is nearest-even). It differs from unorm8_nearest for only 128 floats in [0, 1]:
// those whose product, a hair off a midpoint k + ½, rounds onto it in float and then goes to
// the even side (fl32(0.5/255) = 0.00196078443 stores 0 here, 1 there). NUMERICS.md rule 34.
uint8_t unorm8_llvmpipe(float value);

// The bytes of the rules above, branch-free, for loops the compiler vectorises (the CPU
// device's baseline RGBA8 block store): the same steps on the same floats, so the same bytes
// for every input (tests/cpu_draw/rgba8_store_llvmpipe_test.cpp walks the byte boundaries
// and ties). unorm8_llvmpipe_lane: unorm8_llvmpipe(v); unorm8_nearest_lane: the byte
// unorm8_nearest(v) stands for (round(clamp(v)·255) in double, ties up, NaN → 0).
inline int32_t unorm8_llvmpipe_lane(float v) {
  // NaN and ≤ 0 → 0, ≥ 1 → 255, as the two tests of unorm8_llvmpipe.
  const float low = v > 0.0f ? v : 0.0f;
  const float t = low < 1.0f ? low : 1.0f;
  const float scaled = t * 255.0f; // in [0, 255]: the same fl32 product
  // Truncation is floor here (scaled ≥ 0) and needs no rounding mode; the rest is exact.
  const int32_t k = static_cast<int32_t>(scaled);
  const float rest = scaled - static_cast<float>(k);
  // Ties to even; & and | rather than && and || keep the loop free of branches.
  const int32_t up = (rest > 0.5f ? 1 : 0) | ((rest == 0.5f ? 1 : 0) & (k & 1));
  return k + up;
}
inline int32_t unorm8_nearest_lane(float value) {
  // unorm8_nearest's steps: clamp in double (NaN → 0: the comparisons fail), v·255 exact,
  // + ½ and floor (truncation, the value being ≥ 0).
  const double v = static_cast<double>(value);
  const double t = v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
  return static_cast<int32_t>(t * 255.0 + 0.5);
}

// The float an RGBA8 texel holds for byte k: k/255 correctly rounded (k / 255.0f), as a table
// so that converting a texel costs no division. Every RGBA8 image holds these values.
const std::array<float, 256>& unorm8_levels();

// ---- RGBA16F stores --------------------------------------------------------------------

// The spacing of binary16 values at magnitude `a` (finite, ≥ 0): 2^-24 below 2^-14
// (subnormals), else 2^(e−10) in [2^e, 2^(e+1)). Dividing by it is exact (a power of two),
// so every half rounding is a rounding of a / half_step(a) to an integer.
double half_step(double a);

// Exact: IEEE binary16, round to nearest even; from the midpoint above 65504 (65520) on, ±inf;
// NaN and ±inf kept.
float half_nearest_even(float value);

// lavapipe, when it writes an RGBA16F attachment: rounding toward zero (every one of 65,536
// probe values matched this rule, none matched nearest-even where they differ), so a finite
// value beyond 65504 stores ±65504; NaN and ±inf stay. NUMERICS.md rule 35. Takes a double
// so that a caller holding an exact value rounds it once.
float half_toward_zero(double value);

// The binary16 bit pattern of a float, rounded to nearest even (overflow to inf, NaN kept
// as a quiet NaN), and back: the texel codec of RGBA16F images the Vulkan device uploads
// and reads. For every non-NaN float, half_from_bits(half_bits(x)) == half_nearest_even(x).
uint16_t half_bits(float value);
float half_from_bits(uint16_t bits);

// ---- Denormals (NUMERICS.md rule 13) ---------------------------------------------------

// llvmpipe runs setup, interpolation and texture filtering with the x86 DAZ and FTZ bits
// set: every operand and result below 2^-126 is a zero of its sign. The identity on every
// other value.
inline float flush(float x) {
  return ir::numerics::flush_denormal(x);
}

// ---- Attribute interpolation -----------------------------------------------------------

// lavapipe's evaluation of an attribute plane a0 + dadx·x + dady·y at pixel (x, y): two
// FMAs, each result flushed. The CPU device's per-pixel and block interpolation both call
// it, so they agree bit for bit.
inline float plane_at(float a0, float dadx, float dady, float x, float y) {
  return flush(std::fma(dady, y, flush(std::fma(dadx, x, a0))));
}

// One perspective-corrected channel: the plane's value times 1/w at the pixel, flushed.
inline float perspective_at(float a0, float dadx, float dady, float x, float y, float oow) {
  return flush(plane_at(a0, dadx, dady, x, y) * oow);
}

// ---- Bilinear filtering (lavapipe's float-texture path) --------------------------------

// One axis of a bilinear read: the left (top) texel before addressing and its weight α.
struct LinearAxis {
  int64_t i0 = 0;
  float alpha = 0;
};

// u·N is rounded to float before the weight is taken, and the weight is not quantised: at
// sizes that are not powers of two fl32(u·N) differs from u·N by up to N·2^-24 texel, which
// moves a tap's weight by as much. With clamp-to-edge addressing llvmpipe clamps the
// coordinate, not the index: min(u·N, N) with NaN → N, then − ½, then max(·, 0), so the
// result lies in [0, N − ½]. Other modes keep the coordinate within ±2^40 (far outside any
// address period; NaN → 0) so that the conversion to an integer is defined.
inline LinearAxis linear_axis(float u, uint32_t n, bool clamp_to_edge) {
  const float size = static_cast<float>(n);
  float x = u * size;
  if (clamp_to_edge) {
    x = x < size ? x : size;
    x = x - 0.5f;
    x = x > 0 ? x : 0;
  } else {
    x = x - 0.5f;
    constexpr float kLimit = 1099511627776.0f; // 2^40
    if (std::isnan(x)) x = 0;
    x = x < -kLimit ? -kLimit : (x > kLimit ? kLimit : x);
  }
  const float f = std::floor(x);
  LinearAxis a;
  a.i0 = static_cast<int64_t>(f);
  a.alpha = x - f; // exact (Sterbenz)
  return a;
}

// llvmpipe's lerp: v0 + α·(v1 − v0) as one fused multiply-add, denormal texels and results
// flushed to zeros of their sign.
inline float lerp(float alpha, float v0, float v1) {
  v0 = flush(v0);
  v1 = flush(v1);
  return flush(std::fma(alpha, flush(v1 - v0), v0));
}

// ---- Cube maps (NUMERICS.md, cube maps) ------------------------------------------------

// Where a direction (x, y, z) reads a cube texture: the face (0..5 in D3D9's order +X, −X,
// +Y, −Y, +Z, −Z, which is Vulkan's layer order) and the face coordinates (s, t) in [0, 1].
// The major axis is the component of largest magnitude; on a tie |z| wins over |x| and |y|,
// and |y| over |x| (neither Direct3D 9 nor Vulkan fixes ties; this is lavapipe's choice,
// measured). The face is the positive one unless that component is < 0 (−0 picks +).
// Per face (sc, tc, ma), as Direct3D 9 and Vulkan both tabulate them:
//   +X (−z, −y, x)   −X (z, −y, x)   +Y (x, z, y)   −Y (x, −z, y)   +Z (x, −y, z)   −Z (−x, −y, z)
// and s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2.
struct CubeCoord {
  uint32_t face = 0;
  float s = 0, t = 0;
};
// The face and (sc, tc, |ma|) of the table above, shared by both rules below.
struct CubeAxes {
  uint32_t face = 0;
  float sc = 0, tc = 0, ma = 0; // ma = |major component|
};
CubeAxes cube_axes(float x, float y, float z);
// Exact: s and t computed in double from the float components, rounded once to float.
CubeCoord cube_coord_exact(float x, float y, float z);
// lavapipe: h = fl32(0.5/|ma|), s = fl32(fl32(sc·h) + 0.5), t likewise (measured bit-exact).
CubeCoord cube_coord_llvmpipe(float x, float y, float z);

// ---- Sine and cosine (sincos, NUMERICS.md rule 39) -------------------------------------

// Exact: the double sine or cosine of the float, rounded once to float.
float sin_exact(float a);
float cos_exact(float a);

// lavapipe (Mesa's gallivm, which lowers SPIR-V's GLSL.std.450 Sin and Cos to SSE/AVX code
// rather than calling libm): j = the even integer of trunc(|a|·fl32(4/π)) + 1 (cvttps2dq:
// out of the int32 range, INT32_MIN), r = |a| − j·π/4 in three FMAs with π/4 split in three
// floats, then on the octant's parity sin(r) ≈ r + r³·P(r²) or cos(r) ≈ 1 − r²/2 + r⁴·Q(r²)
// (Cephes' single-precision coefficients, Horner with FMAs), the sign from bit 2 of the
// octant (and a's sign for sin), clamped to [−1, 1] as x86's max then min (a NaN there
// becomes 1); ±inf and NaN arguments give NaN. Denormals are
// flushed in and out of every step. Every float in [−π, π] lands within 2^-23 of the exact
// value (the largest error, found by walking them all, is 7.8e-8 for cos at −2.39); beyond
// |a|·4/π ≥ 2^31 the octant is INT32_MIN's and the result is no sine at all.
float sin_llvmpipe(float a);
float cos_llvmpipe(float a);

// ---- exp2 and log2 (exp, log, pow, lit, expp, logp; NUMERICS.md rule 40) ----------------

// Exact: ir::numerics::FloatArith<Keep>'s exp2 and log2, the C library's (unchanged).

// lavapipe (Mesa's gallivm, which lowers GLSL.std.450 Exp2 and Log2 to its own SSE/AVX code
// rather than calling libm), written from its steps and constants and measured bit for bit
// (tests/vulkan/exp_log_llvmpipe_test.cpp). exp2: a is clamped to [fl32(−126.99999), 128] (NaN
// passes), split into floor(a) and the exact fraction f, and 2^floor(a) (built in the exponent
// field; 0 for −127) multiplies a degree-5 polynomial in f, evaluated as two Horner chains of FMAs
// in f² (even and odd coefficients) joined by one more FMA. log2: a < 0 (−inf included) and NaN
// give NaN, ±0 and denormals −inf, +inf +inf; otherwise the exponent e and the mantissa m in [1, 2)
// are read off a's bits, y = (m − 1)/(m + 1), and log2(a) = e + y·P(y²), P of degree 4 evaluated as
// above, the last step one FMA. Denormals are flushed in and out of every step (rule 13).
float exp2_llvmpipe(float a);
float log2_llvmpipe(float a);

// The fp32 back end of the Direct3D 9 rules (ir/numerics.h) with lavapipe's exp2 and log2:
// what the CPU device runs exp, log, pow, lit, expp and logp on under Rounding::Llvmpipe (D
// Flush or FlushResults). Every other operation is FloatArith's.
template <ir::numerics::Denormals D> struct LlvmpipeArith : ir::numerics::FloatArith<D> {
  static float exp2(float a) { return exp2_llvmpipe(a); }
  static float log2(float a) { return log2_llvmpipe(a); }
};
// ---- Mip levels (NUMERICS.md, mip levels and LOD, M1-M3) --------------------------------
//
// lavapipe's level of detail, written from its sampler's steps (Mesa gallivm) and checked
// by measurement. The exact rules beside them are pass::lod_from_gradients, choose_levels
// and mip_blend_exact (tierlift/pass/mip_lod.h); pass::select_levels picks one or the other.

// ρ of one quad: max(max(|du/dx|, |du/dy|)·W, max(|dv/dx|, |dv/dy|)·H) in float: the larger
// axis-aligned footprint, not the length of the gradient vectors (lavapipe's default
// approximation). Flushed as every float step (rule 13).
inline float mip_rho_llvmpipe(float dudx, float dvdx, float dudy, float dvdy, uint32_t width,
                              uint32_t height) {
  auto larger = [](float a, float b) { return a > b ? a : b; };
  const float s = flush(larger(std::fabs(flush(dudx)), std::fabs(flush(dudy))) * float(width));
  const float t = flush(larger(std::fabs(flush(dvdx)), std::fabs(flush(dvdy))) * float(height));
  return larger(s, t);
}

// log2 by its piecewise-linear approximation: x = m·2^e with m in [1, 2) gives (e − 1) + m,
// exact at powers of two (then e), linear between them; one float add. 0 gives −127.
float fast_log2_llvmpipe(float x);

// λ from ρ: ½·fast_log2(fl32(ρ·ρ)), the square's log halved (both steps in float).
inline float lod_from_rho_llvmpipe(float rho) {
  return 0.5f * fast_log2_llvmpipe(flush(rho * rho));
}

// The nearest level of λ (MIPFILTER POINT): round to nearest, ties to even (the vector
// conversion's default rounding), so λ = 0.5 takes level 0 and 1.5 level 2.
int32_t nearest_level_llvmpipe(float lod);

// The nearest level straight from ρ, when nothing is added to λ and nothing clamps it
// (POINT, no bias of either kind, minLod 0): floor(log2(fl32(ρ·√2))) read off the exponent.
int32_t nearest_level_from_rho_llvmpipe(float rho);

// The mip blend (MIPFILTER LINEAR) is rounding::lerp(fraction, fine, coarse) above, the same
// step as the bilinear lerp, after the fine level's and the coarse level's bilinear reads.
// ---- sRGB reads and writes (NUMERICS.md, sRGB) ----------------------------------------

// IEC 61966-2-1's transfer functions in double: decode c ≤ 0.04045 → c/12.92, else
// ((c + 0.055)/1.055)^2.4; encode l ≤ 0.0031308 → 12.92·l, else 1.055·l^(1/2.4) − 0.055.
double srgb_to_linear_exact(double c);
double linear_to_srgb_exact(double l);

// D3DSAMP_SRGBTEXTURE: the float byte k of an 8-bit texel decodes to, srgb_to_linear_exact(k/255)
// rounded once to float. Both devices read an sRGB stage through this table (before
// filtering); neither uses a driver's own sRGB formats, so the rule is one for every device.
const std::array<float, 256>& srgb_decode_levels();

// D3DRS_SRGBWRITEENABLE: the byte a linear value encodes to, the nearest byte to
// 255·linear_to_srgb_exact(l), found as the count of thresholds at or below l: entry k (1..255)
// is the least float whose encode rounds to k or more (entry 0 is −inf and never compared).
// NaN and l below entry 1 give 0, l ≥ entry 255 (1 included) gives 255. The CPU device and the
// SPIR-V both take it by the same eight-step binary search over the table (srgb_encode_byte).
const std::array<float, 256>& srgb_encode_thresholds();
uint8_t srgb_encode_byte(float linear);
// The colour the blender and the RGBA8 store then take: fl32(byte · kSrgbByteScale), which both
// store rules (unorm8_llvmpipe, unorm8_nearest) turn back into the byte.
inline constexpr float kSrgbByteScale = 1.0f / 255.0f;
float srgb_encoded(float linear);

} // namespace tierlift::rounding
