// Direct3D 7 fixed-function texture-stage state as data: a `.tss` text listing (format in
// docs/stage-states.md), its parser and validator, and its lowering into the IR the shader
// tiers use. A two-stage cascade such as
//
//   stage 0: colorop modulate texture diffuse
//   stage 0: alphaop selectarg1 diffuse
//   stage 1: colorop modulatealpha_addcolor current texture
//
// becomes a ps.1.1 ir::Program (one tex per stage that reads its texture, one instruction per
// operation) and a vs.1.1 ir::Program that passes the quad's position, one texture coordinate
// per stage (uv + c#) and the vertex colours oD0/oD1 (from constants: every vertex of a
// full-screen quad carries the same D3DCOLOR). The interpreter, the SPIR-V back end and the
// analytic model then run it as they run any listing: there is no fixed-function code path.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"
#include "tierlift/ir/source.h"

namespace tierlift::effects::tss {

// D3DTOP_* operations tierlift lowers (a subset of Direct3D 7's list; docs/stage-states.md).
enum class Op {
  Disable,
  SelectArg1,
  SelectArg2,
  Modulate,
  Modulate2x,
  Modulate4x,
  Add,
  AddSigned,
  Subtract,
  ModulateAlphaAddColor, // arg1.rgb + arg1.a · arg2.rgb (colour operations only)
};
// D3DTA_* arguments.
enum class Arg { Current, Diffuse, Specular, Texture, TFactor };

struct Operation {
  Op op = Op::Disable;
  std::vector<Arg> args; // as many as the operation takes
  ir::SourceLoc loc;     // the operation's name, for messages
};

struct Stage {
  std::optional<Operation> color, alpha; // not given: Direct3D's default (docs)
  ir::SourceLoc first;                   // the first line that names the stage
};

struct StageStates {
  std::vector<Stage> stages; // index = stage number; stages after the last named are absent
  uint32_t tfactor = 0;      // D3DRS_TEXTUREFACTOR as 0xAARRGGBB
  ir::SourceLoc tfactor_loc; // invalid when not given
};

// The texture stages a tier has: dx7-class hardware blends two textures in one pass.
inline constexpr uint32_t kDx7Stages = 2;
// Direct3D's own limit on stage numbers (D3DTSS stages 0..7).
inline constexpr uint32_t kD3DMaxStages = 8;

// Parses and validates `file` of `sources` (a .tss text) for a tier with `max_stages`
// texture stages; every problem is a positioned error in `diags` (unknown state or operation,
// a wrong argument count, a stage number or value out of range, a stage past the tier's
// count, a state given twice, a gap in the cascade, a colour-only operation on alpha).
std::optional<StageStates> parse_stage_states(uint32_t file, const ir::SourceManager& sources,
                                              ir::DiagnosticSink& diags,
                                              uint32_t max_stages = kDx7Stages);

// The lowered pair. Vertex constants: c0..c(n−1) the texture coordinate offsets of stages
// 0..n−1 (oT_k = uv + c_k), c8 the diffuse colour, c9 the specular colour (each a D3DCOLOR
// as four floats byte/255, see d3dcolor()). Pixel constant c0 = the texture factor.
struct Lowered {
  std::shared_ptr<const ir::Program> vs, ps;
  std::string vs_text, ps_text; // the listings the IR was read from (for `--explain`, tests)
  uint32_t texture_stages = 0;  // stages whose texture is read (bound to stage 0..n−1)
};
inline constexpr uint32_t kDiffuseConstant = 8, kSpecularConstant = 9;

// Lowers validated states; fails (one error, rule "listing", its message the rendered
// diagnostics) only when the generated listings fail to parse or validate, which would be a
// bug here.
ir::Result<Lowered> lower_stage_states(const StageStates& states);

// Reads, validates and lowers a .tss text: `name` is what messages show. A failure's one
// error (rule "tss") carries the rendered diagnostics as its message.
ir::Result<Lowered> load_stage_states(std::string text, std::string name,
                                      uint32_t max_stages = kDx7Stages);

// A D3DCOLOR byte as the float a device reads from an 8-bit vertex colour: byte / 255.
float d3dcolor_channel(uint8_t byte);

} // namespace tierlift::effects::tss
