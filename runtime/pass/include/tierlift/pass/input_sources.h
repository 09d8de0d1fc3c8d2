// What drives each input of a `tierlift run` pass, said out loud, and the quad-uv vertex
// stage a pixel listing gets without a vertex listing.
//
// Without --vs the pixel stage's inputs used to be constants everywhere (--input, default 0):
// a t# the listing samples with was (0,0,0,0) at every pixel, so the image showed one texel,
// silently. With RunRequest::texcoords_from_quad (what `tierlift run` sets), every t# the
// pixel listing names and --input does not set is the quad's uv instead, interpolated as the
// glow's passes interpolate theirs: prepare_pass then draws with quad_uv_vertex_program,
// which writes oPos = the quad corner, oT# = the quad uv (or the --input constant), oD0/oD1 =
// the --input colours (default 0; as interpolated colours they are saturated to [0, 1], as
// D3D9 does). A listing that names no t# is drawn as before, constants bit for bit.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tierlift/ir/program.h"
#include "tierlift/pass/setup.h"

namespace tierlift::pass {

// One input register and what gives it its value, e.g. {"t0", "quad uv (no --vs)"}.
struct InputSource {
  std::string reg;
  std::string source;
};

// The inputs the request's listings read, each with its driver: without a vertex listing the
// pixel stage's v#/t#; with one, the vertex stage's declared and read v#.
std::vector<InputSource> describe_inputs(const RunRequest& request);

// True when prepare_pass draws `request` through quad_uv_vertex_program: no vertex listing,
// texcoords_from_quad set, and a t# of the pixel listing that no --input sets.
bool uses_quad_uv_stage(const RunRequest& request);

// vs_1_1: dcl_position v0, dcl_texcoord v1; mov oPos, v0; mov oT#, v1 for t# in uv_mask
// (bit n: oTn), mov oT#, c(2 + #) for the others; mov oD0, c0; mov oD1, c1.
std::shared_ptr<const ir::Program> quad_uv_vertex_program(uint8_t uv_mask);

// Fills the pass's vertex stage for uses_quad_uv_stage: program, constants, the quad.
void set_quad_uv_stage(const RunRequest& request, Pass& pass);

} // namespace tierlift::pass
