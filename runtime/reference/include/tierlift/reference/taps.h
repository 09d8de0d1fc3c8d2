// Reading a blur pass's taps off its listings: the vertex listing makes each texture
// coordinate oT# = texcoord input + constant offset, the pixel listing sums
// weight_k · sample(t_k) through mov/add/sub/mul/mad chains. Both are evaluated
// symbolically (every register component as a linear form), so the taps come from the
// listings' own constants and not from a separate description.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tierlift/ir/program.h"

namespace tierlift::ref {

using Vec4 = std::array<float, 4>;

struct Tap {
  uint32_t texcoord = 0;          // oT# / t# whose interpolated coordinate is sampled
  uint32_t sampler = 0;           // s# (ps_2_0, ps_1_4 texld stage) or texture stage (ps_1_x)
  std::array<double, 2> offset{}; // (u, v) added to the texcoord input: the vs constant .xy
  std::array<double, 4> weight{}; // per channel R, G, B, A: the ps constant (ps_1_x: clamped)
};

struct TapExtraction {
  std::vector<Tap> taps;          // in the order the pixel listing first samples them
  uint32_t texcoord_input = 0;    // the vs input register (v#) declared dcl_texcoord
  std::vector<std::string> notes; // assumptions the linear model made (e.g. clamps)
  std::string error;              // non-empty: not of the linear blur form; taps empty
  explicit operator bool() const { return error.empty(); }
};

// vs_consts / ps_consts are the API-set constants c0, c1, …; a `def` in a listing
// overrides them, as in D3D9. Missing constants read 0. ps_1_x constants clamp to [-1, 1].
// Never throws; every listing that is not of the linear form gives an error naming the
// instruction (line:col) that breaks it.
TapExtraction extract_taps(const ir::Program& vs, const std::vector<Vec4>& vs_consts,
                           const ir::Program& ps, const std::vector<Vec4>& ps_consts);

} // namespace tierlift::ref
