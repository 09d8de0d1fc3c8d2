// D3D9's stencil test and stencil operations on an 8-bit stencil buffer, one rule for every
// device that keeps its stencil in host memory (the CPU device) and for the tests that check
// the Vulkan device against it (docs/d3d9-rules.md, "Stencil").
//
//   test:   (ref & read_mask) FUNC (stored & read_mask)  — the reference on the left, as
//           D3DRS_STENCILFUNC documents it (LESS passes when ref < stored).
//   update: stored' = (stored & ~write_mask) | (op(stored) & write_mask), where op is one
//           of D3DSTENCILOP_*: KEEP, ZERO, REPLACE (ref), INCRSAT / DECRSAT (clamped to
//           0..255), INVERT (bitwise), INCR / DECR (wrapping modulo 256).
// The reference and the masks are used modulo 256 (only the buffer's 8 bits take part).
#pragma once

#include <cstdint>

#include "tierlift/pass/pass.h"

namespace tierlift::pass {

inline bool compare_passes(CompareFunc func, uint32_t lhs, uint32_t rhs) {
  switch (func) {
  case CompareFunc::Never: return false;
  case CompareFunc::Less: return lhs < rhs;
  case CompareFunc::Equal: return lhs == rhs;
  case CompareFunc::LessEqual: return lhs <= rhs;
  case CompareFunc::Greater: return lhs > rhs;
  case CompareFunc::NotEqual: return lhs != rhs;
  case CompareFunc::GreaterEqual: return lhs >= rhs;
  case CompareFunc::Always: return true;
  }
  return false;
}

inline bool stencil_test(const DepthStencilState& s, uint8_t stored) {
  const uint32_t mask = s.stencil_read_mask & 0xffu;
  return compare_passes(s.stencil_func, s.stencil_ref & mask, stored & mask);
}

inline uint8_t stencil_update(StencilOp op, const DepthStencilState& s, uint8_t stored) {
  uint32_t v = stored;
  switch (op) {
  case StencilOp::Keep: break;
  case StencilOp::Zero: v = 0; break;
  case StencilOp::Replace: v = s.stencil_ref & 0xffu; break;
  case StencilOp::IncrSat: v = stored == 0xff ? 0xffu : stored + 1u; break;
  case StencilOp::DecrSat: v = stored == 0 ? 0u : stored - 1u; break;
  case StencilOp::Invert: v = ~uint32_t{stored} & 0xffu; break;
  case StencilOp::Incr: v = (stored + 1u) & 0xffu; break;
  case StencilOp::Decr: v = (stored + 0xffu) & 0xffu; break;
  }
  const uint32_t wm = s.stencil_write_mask & 0xffu;
  return static_cast<uint8_t>((stored & ~wm & 0xffu) | (v & wm));
}

} // namespace tierlift::pass
