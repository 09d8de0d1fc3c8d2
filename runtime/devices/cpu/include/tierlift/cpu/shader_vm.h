// Executes one ir::Program per vertex or per pixel with Direct3D 9 semantics (docs/d3d9-rules.md
// §5, §7, §8). It knows nothing of rasterisation: the draw model feeds it interpolated
// inputs and a TextureUnit that samples with the bound sampler state.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "tierlift/ir/conventions.h"
#include "tierlift/ir/program.h"

namespace tierlift::cpu {

using Vec4 = std::array<float, 4>;

// Pixels the block executor (pixel_block.h) runs at once, each register held as four arrays
// of this many lanes (structure of arrays).
inline constexpr int kBlockLanes = 64;
using Lanes = float[kBlockLanes];

// Texture-stage state the ps_1_x texture instructions read (D3DTSS_*).
struct StageState {
  std::array<float, 4> bumpenv_mat{0, 0, 0, 0}; // M00, M01, M10, M11
  float bumpenv_lscale = 0, bumpenv_loffset = 0;
  bool projected = false; // D3DTTFF_PROJECTED: divide by the last coordinate (w)
};

// What the VM asks of the device for every texture read. coord holds (u, v, w, q);
// how many components matter is the bound texture's business (2D: u,v). Unbound stages
// return (0, 0, 0, 1) (docs/d3d9-rules.md §10.6).
class TextureUnit {
public:
  virtual ~TextureUnit() = default;
  virtual Vec4 sample(uint32_t stage, const Vec4& coord, float lod_bias) const = 0;
  virtual StageState stage_state(uint32_t stage) const {
    (void)stage;
    return {};
  }
  // The block executor's read: lanes 0..n−1 at coordinates (coord[0][l], …, coord[3][l]) with
  // bias[l] (nullptr: 0), results into out[c][l]. Must give exactly what n calls of sample()
  // give; this default makes those calls.
  virtual void sample_block(uint32_t stage, const float* const coord[4], const float* bias, int n,
                            Lanes out[4]) const;
};

// API-set constants. Listing defs override these for the shader (as in D3D9).
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
};

struct PixelOutput {
  std::array<Vec4, 4> color{}; // oC0..oC3; ps_1_x: color[0] = r0
  uint8_t color_written = 0;
  std::optional<float> depth;
  bool discarded = false; // texkill
};

class ShaderVM {
public:
  // The program must have passed validation. Throws std::invalid_argument otherwise-broken
  // programs (e.g. unmatched flow control) at construction, never while running.
  ShaderVM(const ir::Program& program, const ir::Conventions& conventions);
  ~ShaderVM();
  ShaderVM(ShaderVM&&) noexcept;
  ShaderVM& operator=(ShaderVM&&) noexcept;

  const ir::Program& program() const;

  // Thread-safe: all per-invocation state lives on the caller's stack.
  VertexOutput run_vertex(const VertexInput& in, const ConstantBank& constants) const;
  PixelOutput run_pixel(const PixelInput& in, const ConstantBank& constants,
                        const TextureUnit& textures) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace tierlift::cpu
