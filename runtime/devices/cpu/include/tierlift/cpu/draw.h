// The CPU device's draw: one pass of Direct3D 9 fixed-function plumbing around the shader
// VM — vertex stage, clipping, viewport transform, rasterisation with the top-left fill
// rule, perspective-correct interpolation, pixel stage, texkill, blending, store
// (docs/d3d9-rules.md §9, §10; docs/design.md "Conventions").
//
// How the geometry is placed:
//   * Screen space: x_s = X + (x/w + 1)·W/2, y_s = Y + (1 − y/w)·H/2 (y down).
//   * Pixel (i, j) is sampled at (i, j) under PixelCenter::D3D9 and at (i + 0.5, j + 0.5)
//     under PixelCenter::Modern. So the full-screen quad interpolates u = i/W at pixel i
//     with D3D9 centres and (i + 0.5)/W with modern ones.
//   * Vertices are snapped to 1/256 pixel (8 sub-pixel bits, as lavapipe) and the edge
//     functions are evaluated exactly in integers: a pixel whose sample point lies on an
//     edge is drawn only when that edge is a top or left edge, so two triangles sharing an
//     edge never both draw a pixel and never both miss one.
//   * Clipping: 0 ≤ z ≤ w (D3D9's clip volume) and a guard band |x|, |y| ≤ 8·w; pixels
//     outside the viewport and the target are not drawn.
//
// No culling (D3DCULL_NONE): both windings are drawn. A stencil test on an 8-bit stencil
// buffer when pass.depth_stencil.stencil_test, a depth test on a float depth buffer when
// pass.depth_stencil.depth_test (DrawTargets below; not both in one pass yet).
//
// Interpolation: oT# and oD# are perspective-correct (oD# saturated per vertex first, and
// clamped to [0, 1] again per pixel); z/w is interpolated linearly in screen space into
// PixelInput::depth (under Rounding::Llvmpipe with lavapipe's z plane, else from the exact
// edge functions in double: NUMERICS.md D4). How the rounding goes is
// pass.conventions.rounding (ir::Rounding), a device-matching choice, since D3D9 leaves it to
// the hardware:
//   * Llvmpipe (default): Mesa llvmpipe's arithmetic, so that the CPU device and the Vulkan
//     device on lavapipe compute bit-identical texture coordinates at every target size
//     (u = i/1920 is not a float; any two schemes round it differently, and the bilinear
//     weights follow). Per triangle, in float without fused operations: the vertices'
//     float screen positions as lavapipe's viewport transform makes them (fma(x·(1/w), W/2,
//     X + W/2 + ½ for D3D9 centres)), each attribute times 1/w, and the plane a0 + dadx·i +
//     dady·j through the three vertices with a0 referred to pixel (0, 0)'s sample point;
//     per pixel: fma(dady, j, fma(dadx, i, a0)) for the attribute and for 1/w, then
//     attribute · (1 / (1/w)). Bilinear sampling likewise takes lavapipe's float path
//     (texture.h, sample_texture_llvmpipe). Clipped vertices are the CPU clipper's, so
//     clipped triangles may differ from lavapipe by an ulp. Equal non-finite values at the
//     three vertices stay themselves.
//   * Exact: barycentric weights from the exact integer edge functions, in double, divided
//     by the interpolated 1/w when the three w differ, rounded to float once; bilinear
//     weights from u·N − 0.5 in double (sample_texture).
// Measured (Listings 1+2, 8 bilinear taps of noise, 1920×1080, subtexel_bits 0): Exact
// differs from lavapipe by up to 6e-5 (RGBA32F) and 99.5 % identical pixels (RGBA8);
// Llvmpipe is bit-identical in RGBA32F and, with lavapipe's RGBA8 store and blend (below), in
// RGBA8 too (99.998 % with the exact store rule).
//
// Store: the pixel stage's oC0 (ps_1_x: r0; no pixel program: the interpolated oD0, as
// D3D9's fixed function with no texture passes the diffuse colour) is blended with the stored
// destination value and stored (blend_and_store). Float and half targets, and RGBA8 under
// Rounding::Exact: blended in float, quantised with img::quantize(target.format), the source
// colour and blend factors clamped to [0, 1] first for RGBA8 as Vulkan and D3D9 do for UNORM
// attachments. RGBA8 under Rounding::Llvmpipe: lavapipe's way — the source converted with
// rounding::unorm8_llvmpipe (ties to even of fl32(x·255)), then blended in 8-bit integers
// (NUMERICS.md rule 34). Blending applies to all four channels.
//
// Threads: rows are handed out in small bands to `threads` workers (0 = every core). Each
// pixel is written by exactly one worker, in primitive order, so the image does not depend
// on the thread count.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/cpu/shader_vm.h"
#include "tierlift/cpu/texture.h"
#include "tierlift/image/image.h"
#include "tierlift/ir/conventions.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"

namespace tierlift::cpu {

// The pass a draw takes is the device-neutral pass state (tierlift/pass/pass.h).
using pass::BlendMode;
using pass::Executor;
using pass::kQuadCorners;
using pass::kQuadTriangles;
using pass::kQuadUV;
using pass::Pass;
using pass::set_full_screen_quad;
using pass::Viewport;

// What the CPU device draws beyond one colour target with programmable stages: up to four
// render targets (oC0..oC3) and a stencil buffer or a depth buffer.
inline constexpr pass::Capabilities kCapabilities{.max_color_targets = 4, .depth_stencil = true};

// The rule of a failed draw.
inline constexpr std::string_view kDrawRule = "draw";

// Where one draw writes. color[i] receives oC#i for i < pass.color_targets (every one of them
// set and of color[0]'s size; each has its own format and store rule, the blend mode is
// shared, as D3D9's one D3DRS_ALPHABLENDENABLE). `stencil`: color[0]'s width × height bytes,
// row by row; required when pass.depth_stencil.stencil_test. Per pixel, after the pixel
// stage and texkill (a killed pixel touches neither colour nor stencil), the stencil test
// (tierlift/pass/stencil.h) decides: failed → stencil_fail op, no colour; passed →
// stencil_pass op, the colours are blended and stored.
struct DrawTargets {
  std::array<img::Image*, 4> color{};
  uint8_t* stencil = nullptr;
  // `depth`: color[0]'s width × height floats, row by row; required when
  // pass::uses_depth(pass.depth_stencil). Per pixel, after texkill (a killed pixel writes no
  // depth), with ZENABLE (depth_test): the pixel's depth (oDepth or the interpolated z/w,
  // clamped to [0, 1]) is tested against the stored one with depth_func; failed → nothing is
  // written; passed → the depth is stored when depth_write, and the colours are stored
  // (pass/depth.h, NUMERICS.md D1-D4).
  float* depth = nullptr;
  // The colour targets hold leftovers that stand for zeros (a device reusing a buffer it has
  // not cleared). The draw zeroes them before it writes, unless it overwrites every pixel
  // without reading one: one target, blend Replace, no stencil test, no texkill in the pixel
  // program, and the triangles covering the whole target — a full-screen pass then costs no
  // clear. A draw that fails leaves them as they were (still stale).
  bool stale = false;
};

// What a draw did.
struct DrawStats {
  uint64_t triangles = 0;     // after clipping
  uint64_t pixels_shaded = 0; // pixel-stage invocations
  uint64_t pixels_killed = 0; // discarded by texkill
  uint64_t pixels_block = 0;  // of pixels_shaded, those the block executor ran
};

// Draws `pass` into `target` (its format decides the store rule). Never throws on bad
// input: a program the VM cannot run, an index out of range or a target larger than
// img::kMaxDimension is a failure (rule kDrawRule, no subject) that says why nothing was
// drawn, and leaves the target unchanged.
ir::Result<DrawStats> draw(const Pass& pass, img::Image& target, unsigned threads = 0);
// The same into several render targets and a stencil or depth buffer (DrawTargets). Passes with
// more than one target or a depth/stencil state take the per-pixel executor.
ir::Result<DrawStats> draw(const Pass& pass, const DrawTargets& targets, unsigned threads = 0);

// One pixel of a draw, traced (tierlift run --trace): the pixel program run at pixel (x, y)
// of a width × height target with the inputs the draw gives it there — those of the last
// triangle covering the pixel, in primitive order — recording every instruction's
// destination (InstructionTrace). The per-pixel VM runs it; the block executor a draw may
// take gives the same values bit for bit (tests/cpu_draw/executor_identity_test.cpp).
struct PixelTrace {
  bool covered = false; // no triangle covers the pixel (or it lies outside the viewport)
  InstructionTrace trace;
  PixelOutput output;
};
// Fails (rule kDrawRule) where draw() would, or when the pass has no pixel program or (x, y)
// lies outside the target.
ir::Result<PixelTrace> trace_pixel(const Pass& pass, uint32_t width, uint32_t height, uint32_t x,
                                   uint32_t y);

// Blend `src` onto the stored `dst` and quantise for `format` (the per-pixel store rule,
// exposed for tests). `rounding` is the pass's ir::Conventions::rounding: for RGBA8 targets
// Llvmpipe converts the source with rounding::unorm8_llvmpipe and blends in 8-bit integers as
// lavapipe does (NUMERICS.md rule 34); Exact, and every other format, blend in float and store
// with img::quantize.
Vec4 blend_and_store(BlendMode mode, img::Format format, const Vec4& src, const Vec4& dst,
                     ir::Rounding rounding = ir::Conventions{}.rounding);

} // namespace tierlift::cpu
