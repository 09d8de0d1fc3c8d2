// Internal to tap extraction: symbolic evaluation of the two listings.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/analytic/taps.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"

namespace tierlift::analytic::detail {

// "line 12:5" of an instruction or operand (listings from bytecode have no lines).
std::string where(const ir::SourceLoc& loc);

// c# as the shader sees it: a `def` in the listing (`defs`, folded once per program) wins
// over the API-set value; missing registers read 0. `clamped` is set when ps_1_x clamping to
// [-1, 1] changed a component.
std::array<double, 4> constant_value(const ir::FoldedDefs& defs, const std::vector<Vec4>& api,
                                     uint32_t index, bool ps1x_clamp, bool* clamped);

// Source modifiers that are affine maps x → scale·x + bias (docs/d3d9-rules.md §4.2).
struct AffineMod {
  double scale = 1, bias = 0;
};
std::optional<AffineMod> affine_modifier(ir::SrcMod mod);

// Vertex side: oT# = texcoord input · scale + constant, per coordinate register and axis.
struct CoordAffine {
  std::array<double, 2> scale{1, 1}, offset{};  // .xy
  std::array<std::array<float, 2>, 4> corner{}; // .xy at the quad's corners, in fp32 (Tap)
};
// A vertex colour oD0/oD1 that is the same constant at every vertex (a full-screen quad's
// D3DCOLOR), as the pixel stage reads it: saturated to [0, 1] (NUMERICS.md rule 26).
using ColourConstants = std::array<std::optional<std::array<double, 4>>, 2>;

// "" when `vs` is a vertex and `ps` a pixel listing and both pass ir::validate_ir (the
// structural checks every backend runs first), else why not: `who` needs a pair, or the
// first validate_ir error, naming the listing.
std::string structural_error(std::string_view who, const ir::Program& vs, const ir::Program& ps);

// A failure of the public extract_* / check_* functions (taps.h: kFormRule).
ir::Failure form_failure(std::string message);

struct CoordForms {
  uint32_t texcoord_input = 0;
  ColourConstants colour;                          // per oD#: set when it is a constant
  std::array<std::optional<CoordAffine>, 8> coord; // per oT#
  std::array<std::string, 8> why_not;              // when coord is empty: the reason
  std::string error;                               // fatal: the listing cannot be evaluated at all
};
CoordForms evaluate_coords(const ir::Program& vs, const std::vector<Vec4>& consts);

// Pixel side: the output as Σ weight_k · sample_k.
struct SumForm {
  std::vector<Tap> taps; // offset not filled in
  std::vector<std::string> notes;
  std::string error;
};
// v0/v1 read `colours`' constants where set (lowered fixed-function stages carry their
// weights as vertex colour); any other v# read makes the form opaque.
SumForm evaluate_sum(const ir::Program& ps, const std::vector<Vec4>& consts,
                     const ColourConstants& colours = {});

// Fills each tap's offset and scale from its oT#'s form; an error when that oT# has none.
std::string place_taps(const CoordForms& coords, std::vector<Tap>& taps);

// The (texcoord, sampler) a sampling instruction reads, nullopt for an instruction that
// samples nothing, or a failure (rule "analytic", naming the instruction) for a read the
// model cannot place (dependent or modified coordinates, texture ops other than plain
// samples).
ir::Result<std::optional<std::pair<uint32_t, uint32_t>>> sample_key(const ir::Instruction& in);

} // namespace tierlift::analytic::detail
