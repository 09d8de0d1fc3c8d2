// Where a pixel program's values are "plain": +0 or a positive normal number, never −0, a
// denormal, an infinity or a NaN. For such values two of the legacy rules change nothing:
//   - rule 8 (0 × anything = +0): with both factors plain, x·y is already +0 when either is
//     zero (x is +0 then, and +0 · y = +0 for y ≥ +0 finite), so the plain product is the
//     rule's value in every denormal mode (rule::mul_plain);
//   - the ps_1_x register range clamp to ±max (rules 24, 25): a plain result at most max is
//     left as it is, and its min/max flush has no denormal to flush.
// An RGBA8 texel decoded to k/255.0f is plain (0 or 1/255 … 1), and so are products and
// sums of such texels with positive weights: the glow's blur, downsample and composite
// passes. The Vulkan code generator leaves out what these facts make redundant; the
// interpreter runs the rules in full (the two still agree bit for bit, which the tests
// check on values chosen to sit on each edge of the facts).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tierlift/ir/program.h"

namespace tierlift::ir {

struct PlainValueFacts {
  // Per instruction of program.code, per source operand (the first four): the components,
  // as the instruction reads them (after the swizzle, the modifier and the ps_1_x constant
  // clamp), known to be plain.
  std::vector<std::array<uint8_t, 4>> sources;
  // Per instruction: its result is plain and at most the ps_1_x range's max in every
  // component it writes, before the range clamp (false where no clamp applies).
  std::vector<bool> within_ps1x_range;
};

struct PlainValueInputs {
  // c# as the device binds them (a def wins over the bank); a register past the end is
  // not known.
  std::span<const std::array<float, 4>> constants;
  // The sampler stages whose reads return an RGBA8 texel decoded to k/255.0f exactly
  // (bit s for stage s): the Vulkan device's in-place reads (stage_fetch_unorm8).
  uint32_t unorm8_stages = 0;
  float ps1x_max = 1.0f;   // the ps_1_x range (Conventions::ps1x_max_value)
  int ps1x_fixed_bits = 0; // > 0: ps_1_x results are quantised (a result then is not known)
};

// The facts, found by one forward walk over straight-line code: at the first flow-control
// instruction (vs_2_0 flow, ps_1_4 phase) everything becomes unknown again. Co-issued
// instructions read the registers as they were before the pair, as the devices do.
PlainValueFacts plain_values(const Program& program, const PlainValueInputs& in);

} // namespace tierlift::ir
