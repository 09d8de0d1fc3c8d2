// Reading a pass's taps off its listings: the vertex listing makes each texture coordinate
// an affine map of the quad's texcoord input, one scale and one offset per axis
// (oT# = v·scale + offset: Listings 1 and 3 add an offset, glow/quad4_coords.vsh also
// scales), the pixel listing sums weight_k · sample(t_k) through mov/add/sub/mul/mad chains,
// reading one texture or several (one per sampler stage). Both are evaluated symbolically
// (every register component as a linear form), so the taps come from the listings' own
// constants and not from a separate description.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"

namespace tierlift::analytic {

using Vec4 = std::array<float, 4>;

struct Tap {
  uint32_t texcoord = 0;             // oT# / t# whose interpolated coordinate is sampled
  uint32_t sampler = 0;              // s# (ps_2_0, ps_1_4 texld stage) or texture stage (ps_1_x)
  std::array<double, 2> offset{};    // (u, v) added to the texcoord input: the vs constant .xy
  std::array<double, 2> scale{1, 1}; // (u, v) the texcoord input is multiplied by first
  std::array<double, 4> weight{};    // per channel R, G, B, A: the ps constant (ps_1_x: clamped)
  // oT#.xy at the full-screen quad's corners (top-left, top-right, bottom-left, bottom-right;
  // texcoord input (0,0), (1,0), (0,1), (1,1)) as the vertex listing computes them in fp32,
  // one rounding per instruction. Set by extract_taps / extract_reads; with them the model
  // interpolates the coordinate as the devices do (quad_coords.h) instead of in double.
  std::optional<std::array<std::array<float, 2>, 4>> corners;
  // With corners: an fp32 (u, v) the pixel listing adds to the interpolated coordinate, one
  // fp32 add per axis (tier dx9c's `add r1.xy, v0, c[aL]`); `offset` is then the same value.
  std::optional<std::array<float, 2>> pixel_add;
};

struct TapExtraction {
  std::vector<Tap> taps;          // in the order the pixel listing first samples them
  uint32_t texcoord_input = 0;    // the vs input register (v#) declared dcl_texcoord
  std::vector<std::string> notes; // assumptions the linear model made (e.g. clamps)
};

// The rule of every failure below: the listings are not of the form the model knows (one
// error, subject "analytic", whose message names the listing and the instruction).
inline constexpr std::string_view kFormRule = "analytic-form";

// vs_consts / ps_consts are the API-set constants c0, c1, …; a `def` in a listing
// overrides them, as in D3D9. Missing constants read 0. ps_1_x constants clamp to [-1, 1].
// Never throws; every listing that is not of the linear form gives an error naming the
// instruction (line:col) that breaks it. Tap coordinates: u' = scale.u·u + offset.u (and v),
// where u is the texcoord input; a coordinate with a cross term (u' depending on v) or a
// non-finite scale is not of the form.
ir::Result<TapExtraction> extract_taps(const ir::Program& vs, const std::vector<Vec4>& vs_consts,
                                       const ir::Program& ps, const std::vector<Vec4>& ps_consts);

// Every texture read the pixel listing takes, in order of first appearance, with its
// coordinate from the vertex listing (weight left at 0), whatever the listing computes from
// the reads: the analytic device's non-linear forms (rgb × alpha) say themselves what is
// done with them. Errors as extract_taps (dependent reads, coordinates not of the form).
ir::Result<std::vector<Tap>>
extract_reads(const ir::Program& vs, const std::vector<Vec4>& vs_consts, const ir::Program& ps);

// The full-screen quad's position: the analytic model assumes the vertex listing passes its
// position input (dcl_position, v0 when none is declared) to oPos unchanged, as every glow
// listing does (`mov oPos, v0`). Fails (kFormRule) naming the instruction when it does not.
ir::Status check_position_passthrough(const ir::Program& vs);

} // namespace tierlift::analytic
