// The block executor's store: an instruction's result lanes into the destination register
// through vm::dst_transform's steps (shift, ps_1_x range clamp, saturate, fixed point), each a
// lane loop the compiler vectorises (TL_INLINE: vm_block_internal.h).
#pragma once

#include <cstring>

#include "tierlift/ir/numerics.h"
#include "vm_block_internal.h"

namespace tierlift::cpu::block {

namespace num = ir::numerics;

// The ps_1_x range clamp (rules 24, 25: numeric_rules.h clamp_sym) of one block of lanes, in
// the form the vectoriser maps onto one max and one min. It is clamp_sym bit for bit when
// max >= 1: clamp_sym compares x after flushing it (under Denormals::Flush), but a denormal
// and the zero it flushes to both lie strictly inside ±max, so the compares come out the same
// either way; and `lo > v ? lo : v`, `max < v ? max : v` keep a NaN, as clamp_sym's selects
// do (executor_identity_test holds the block path to the per-pixel VM on such values).
template <num::Denormals D> TL_INLINE void range_clamp(const float* in, float* o, float max) {
  const float lo = -max;
  for (int l = 0; l < L; ++l) {
    float v = in[l];
    v = lo > v ? lo : v;
    v = max < v ? max : v;
    o[l] = num::dz<D>(v);
  }
}

// The result `v` of one instruction into its register `r` through the destination's steps.
template <num::Denormals D>
TL_INLINE void store_lanes(const vm::DstDesc& d, const LaneVec4& v, LaneVec4& r) {
  for (int c = 0; c < 4; ++c) {
    if (!(d.mask & (1 << c))) continue;
    // vm::dst_transform's steps in its order, one lane loop per step the destination has:
    // one loop with all four would compute every step on every lane and select. The first
    // step reads the result where it lies and writes the register: copying first and then
    // transforming the copy stalls each load on the store just before it.
    const float* in = v.c[c];
    float* o = r.c[c];
    if (d.plain) {
      if (in != o) std::memcpy(o, in, sizeof(Lanes));
      continue;
    }
    if (d.scale != 1.0f) {
      for (int l = 0; l < L; ++l) o[l] = num::legacy_scale<D>(in[l], d.scale);
      in = o;
    }
    if (d.range && d.max_value >= 1.0f) {
      range_clamp<D>(in, o, d.max_value);
      in = o;
    }
    if (in != o) std::memcpy(o, in, sizeof(Lanes));
    if (d.range && d.max_value < 1.0f)
      for (int l = 0; l < L; ++l) o[l] = num::legacy_ps1x_range<D>(o[l], d.max_value);
    if (d.sat)
      for (int l = 0; l < L; ++l) o[l] = num::legacy_saturate<D>(o[l]);
    if (d.fixed_bits > 0)
      for (int l = 0; l < L; ++l)
        o[l] = num::legacy_fixed_quantise<D>(o[l], d.fixed_bits, d.max_value);
  }
}

} // namespace tierlift::cpu::block
