// D3D9's depth buffer as one rule for every device that keeps it in host memory (the CPU
// device) and for the tests that check the Vulkan device against it (NUMERICS.md, "Depth
// buffer"; docs/d3d9-rules.md, "Depth buffer").
//
//   value: the pixel's depth is oDepth when the pixel program writes it (ps_2_0 and later,
//          ps_1_x texdepth / texm3x2depth), else the interpolated z/w of the position; either
//          is clamped to the viewport's depth range [0, 1] by rule 23's saturate, so NaN
//          becomes 0 (the SPIR-V clamps oDepth with the same select before it writes
//          FragDepth, so lavapipe never sees a value outside [0, 1]).
//   test:  fragment FUNC stored — the incoming value on the left, as D3DRS_ZFUNC documents it
//          (LESS passes when the new pixel is nearer, smaller z). A failed test writes neither
//          colour nor depth; a passed one writes the depth when ZWRITEENABLE is on.
//   ZENABLE off (DepthStencilState::depth_test false) means no test and no write, whatever
//   ZWRITEENABLE says: D3D9 writes depth only while z-buffering is on, as Vulkan does.
#pragma once

#include <cmath>
#include <string_view>

#include "tierlift/ir/numerics.h"
#include "tierlift/pass/pass.h"

namespace tierlift::pass {

// DepthStencilState's depth fields are D3DRS_ZENABLE (depth_test), D3DRS_ZWRITEENABLE
// (depth_write: it writes only while depth_test is on) and D3DRS_ZFUNC (depth_func, default
// LESSEQUAL). A pass with either flag draws with a depth buffer (a float per pixel); a device
// binds a depth buffer or a stencil buffer, not both in one pass yet.
inline bool uses_depth(const DepthStencilState& ds) {
  return ds.depth_test || ds.depth_write;
}

// The depth a pixel takes to the test and the buffer: `written` (oDepth) when the program
// wrote it, else `interpolated`, clamped to [0, 1] (NaN → 0; denormals flushed to 0 when
// `flush`, as lavapipe's compare does).
inline float fragment_depth(const float* written, float interpolated, bool flush) {
  const float z = written ? *written : interpolated;
  return flush ? ir::numerics::legacy_saturate<ir::numerics::Denormals::Flush>(z)
               : ir::numerics::legacy_saturate<ir::numerics::Denormals::Keep>(z);
}

// D3DRS_ZFUNC: `fragment` FUNC `stored`, in float (a NaN compares false except NOTEQUAL,
// whose IEEE != is true; neither device stores a NaN, fragment_depth never makes one, and an
// initial buffer is checked for NaN where it is read).
inline bool depth_passes(CompareFunc func, float fragment, float stored) {
  switch (func) {
  case CompareFunc::Never: return false;
  case CompareFunc::Less: return fragment < stored;
  case CompareFunc::Equal: return fragment == stored;
  case CompareFunc::LessEqual: return fragment <= stored;
  case CompareFunc::Greater: return fragment > stored;
  case CompareFunc::NotEqual: return fragment != stored;
  case CompareFunc::GreaterEqual: return fragment >= stored;
  case CompareFunc::Always: return true;
  }
  return false;
}

// D3DCMPFUNC names as `tierlift run --depth-func` takes them (case-insensitive, with or
// without the D3DCMP_ prefix): never, less, equal, lessequal, greater, notequal,
// greaterequal, always. False for any other word.
bool parse_compare_func(std::string_view word, CompareFunc& out);
std::string_view compare_func_name(CompareFunc func);

} // namespace tierlift::pass
