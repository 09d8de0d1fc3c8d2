// Random valid shader listings and the delta reducer that shrinks a failing one: the
// generated corpus of `tierlift test --generate` checks the translation where no hand-written
// test looks (docs/generate.md).
//
// The generator walks the opcode table (ir/opcodes.h) and the profile limits (ir/profile.h):
// every row legal in the profile, with random destinations, write masks, swizzles, source
// and instruction modifiers and register files. Each instruction it proposes is kept only
// when the program with it (and the tail that closes blocks and writes the outputs) passes
// the project's validator, so every listing it returns validates by construction. The
// shapes a profile imposes come from the builder: ps_1_x texture stages and phases, flow
// blocks and subroutines from vs_2_0 on, predicates (setp, (p0) instructions, if p0,
// breakp) and if_comp / break_comp in the 2.x and 3.0 profiles, vs_3_0's o# declared with
// a semantic (o0 the position), ps_3_0's v# with drawn semantics, vPos and vFace, and
// relative v# / o# inside loops (docs/generate.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>

#include "tierlift/ir/profile.h"
#include "tierlift/ir/result.h"

namespace tierlift::gen {

struct GenerateOptions {
  // Instructions proposed for the body (before the output writes); the profile's slot
  // limits may keep fewer.
  std::size_t min_instructions = 4, max_instructions = 16;
  // ps_2_0, ps_2_x, ps_3_0: declare 2D samplers only (a harness that binds 2D textures).
  // false: also cube and volume samplers. (vs_3_0's vertex samplers are always 2D.)
  bool only_2d_samplers = false;
  // ps_2_0, ps_2_x, ps_3_0: also write oC1 and oDepth sometimes; false: oC0 only (one
  // render target).
  bool extra_outputs = true;
};

// A valid random listing (assembly text) of `profile` ("ps_2_0", "vs_1_1", ...),
// deterministic in (profile, seed, index, options). Fails (rule "usage", subject
// "--profile") for a profile the front end does not know and for one the generator does not
// write (generates).
ir::Result<std::string> generate_listing(std::string_view profile, std::uint64_t seed,
                                         std::size_t index, const GenerateOptions& options);
// The profiles it writes: every profile the front end knows (vs_1_1 ... vs_3_0, ps_1_1 ...
// ps_3_0). A profile added to ir::Profile stays refused until the builder has its shapes.
bool generates(ir::Profile profile);
// "vs_1_1, vs_2_0, ..." : the profiles generates() takes, in ir::kAllProfiles order (the
// CLI's help text and the refusal message).
std::string generated_profile_names();
// The profile named `name` when the generator writes it; else why not (generate_listing's
// failures).
ir::Result<ir::Profile> generated_profile(std::string_view name);
ir::Result<std::string> generate_listing(std::string_view profile, std::uint64_t seed,
                                         std::size_t index);

// What a set of listings exercises, counted by name: the figures `tierlift generate` prints
// and the coverage tests check.
struct Coverage {
  std::size_t listings = 0, invalid = 0;      // invalid: did not parse or validate (not counted)
  std::map<std::string, std::size_t> opcodes; // "mad", "texm3x3spec"
  std::map<std::string, std::size_t> source_modifiers;      // "negate (-)", "_bx2", "1-"
  std::map<std::string, std::size_t> instruction_modifiers; // "_sat", "_pp", "+", "(p0)"
  std::map<std::string, std::size_t> register_files; // "r", "oPos", "c[a0]", "v[aL]", "o[aL]"
  std::map<std::string, std::size_t> swizzles;       // ".xyzw" for identity, ".x", ".wzyx"
  std::map<std::string, std::size_t> write_masks;    // ".xyzw" for full, ".xy"
  // "dcl_texcoord v", "dcl_position o", "dcl_2d s", "dcl vPos": statement and register file.
  std::map<std::string, std::size_t> declarations;
  void add(const std::string& listing);
  std::string summary() const; // one line per category: "opcodes 32: abs add ..."
};

// Delta reduction: the smallest listing found that still satisfies still_fails (the
// predicate decides validity and failure). Lines first (ddmin over the statements after the
// version line), then operands (swizzles and masks dropped, modifiers dropped, sources
// replaced by c0, else c1), repeated until nothing more goes. Deterministic. `text` itself must
// satisfy the predicate; otherwise it is returned unchanged.
std::string reduce_listing(const std::string& text,
                           const std::function<bool(const std::string&)>& still_fails);

} // namespace tierlift::gen
