// The conventions every device must state explicitly (docs/design.md "Conventions"): one struct,
// one place. The interpreter, the analytic model and the Vulkan device all read it.
#pragma once

#include "tierlift/ir/ps1x_range.h"

namespace tierlift::ir {

enum class PixelCenter {
  D3D9,   // pixel (i, j) centred at integer screen position (i, j)
  Modern, // centred at (i + 0.5, j + 0.5) as in D3D10+, GL, Vulkan
};

// Where D3D9 leaves the rounding to the hardware — attribute interpolation, the bilinear
// filter's arithmetic, the stores — the CPU device either reproduces Mesa's llvmpipe
// (lavapipe) bit for bit or computes exactly; tierlift/rounding/rounding.h holds both, rule
// beside rule. A device-matching choice: the Vulkan device ignores it (but for
// the def denormals the code generator loads flushed under Llvmpipe).
enum class Rounding {
  // Float plane equations a0 + dadx·x + dady·y evaluated with FMA, times 1/w; bilinear
  // weights frac(fl32(u·N) − 0.5) in float, lerps with FMA.
  // Denormals flushed in and out of every operation, def denormals loaded as zeros, on the
  // CPU device and in the emitted SPIR-V (NUMERICS.md rule 13).
  Llvmpipe,
  // Perspective-correct barycentrics from exact edge functions and bilinear weights from
  // u·N − 0.5, both in double, rounded once. Denormals kept (IEEE).
  Exact,
};

struct Conventions {
  PixelCenter pixel_center = PixelCenter::D3D9;
  // Sub-texel precision of bilinear weights: 0 = exact, N = fractions quantised to N bits
  // (lavapipe reports 8, but its float-texture path does not quantise: 0 matches it).
  int subtexel_bits = 0;
  // ps_1_x: registers clamp to [-max, +max] (PixelShader1xMaxValue; the default is the
  // d3d9 preset of ps1x_range.h, what D3D9 runtimes report). Constants always clamp to [-1, 1].
  float ps1x_max_value = default_ps1x_max();
  // ps_1_x fixed-point emulation: 0 = off (fp32), 8 or 9 = fraction bits of the hardware.
  int ps1x_fixed_bits = 0;
  // Llvmpipe (default) makes the CPU and Vulkan devices agree at every target size.
  Rounding rounding = Rounding::Llvmpipe;
};

} // namespace tierlift::ir
