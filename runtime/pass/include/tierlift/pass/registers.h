// The register values a pass hands to a device: API-set constants, vertex inputs, vertex
// outputs (for pre-transformed geometry) and constant pixel inputs. Device-neutral: the CPU
// interpreter runs on them directly, the Vulkan device packs them into uniform blocks and
// vertex buffers, the analytic model reads the constants.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace tierlift::pass {

using Vec4 = std::array<float, 4>;

// Texture-stage state the ps_1_x texture instructions read (D3DTSS_*).
struct StageState {
  std::array<float, 4> bumpenv_mat{0, 0, 0, 0}; // M00, M01, M10, M11
  float bumpenv_lscale = 0, bumpenv_loffset = 0;
  bool projected = false; // D3DTTFF_PROJECTED: divide by the last coordinate (w)
};

// API-set constants of one stage: the one constant bank from `--const` to every device.
// Listing defs override these for the shader (as in D3D9).
struct ConstantBank {
  std::vector<Vec4> f; // c#, any size; missing registers read (0,0,0,0)
  std::array<std::array<int32_t, 4>, 16> i{};
  std::array<bool, 16> b{};
};

struct VertexInput {
  std::array<Vec4, 16> v; // missing components read (0,0,0,1)
  VertexInput() { v.fill({0, 0, 0, 1}); }
};

struct VertexOutput {
  Vec4 pos{0, 0, 0, 1};
  std::array<Vec4, 2> color{}; // oD0, oD1 (not yet saturated; the rasteriser saturates)
  std::array<Vec4, 8> tex{};   // oT0..oT7
  float fog = 0, point_size = 0;
  uint8_t color_written = 0; // bit n: oDn written
  uint8_t tex_written = 0;   // bit n: oTn written
};

struct PixelInput {
  std::array<Vec4, 2> color{}; // v0, v1 in [0,1]
  std::array<Vec4, 8> tex{};   // TC(0..7), interpolated texture coordinates
  float depth = 0;             // interpolated z (for texdepth / texm3x2depth defaults)
  // ps_3_0 vPos: the pixel's integer coordinates (x, y), pixel centres at integers as in
  // Direct3D 9 (NUMERICS.md "vPos"); vFace: +1 for a front face (clockwise on screen, the
  // Direct3D 9 default), -1 for a back face (NUMERICS.md "vFace").
  float pos_x = 0, pos_y = 0;
  float face = 1;
};

} // namespace tierlift::pass
