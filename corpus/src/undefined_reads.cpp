// The interpreter run that decides NUMERICS.md rule 38: the pixel program at the pass's
// constant inputs, its texture reads watched by a TextureUnit that forwards every read to the
// device's own sampler and notes the first whose coordinate is not finite.
#include "tierlift/corpus/undefined_reads.h"

#include <cmath>

#include <fmt/format.h>

#include "tierlift/cpu/shader_vm.h"
#include "tierlift/cpu/texture.h"

namespace tierlift::corpus {
namespace {

// How many coordinate components stage s addresses: xyz for a cube or volume declared in a
// ps_2_0 program, xy otherwise (2D, and the ps_1_x stages the run binds 2D textures to).
int addressed_components(const ir::Program& p, uint32_t stage) {
  for (const ir::Declaration& d : p.decls)
    if (d.reg.file == ir::RegFile::Sampler && d.reg.index == stage &&
        (d.sampler_type == ir::SamplerType::Cube || d.sampler_type == ir::SamplerType::Volume))
      return 3;
  return 2;
}

// A coordinate component as the message shows it: NaN without its sign bit's "-".
std::string show(float v) {
  return std::isnan(v) ? "nan" : fmt::format("{}", v);
}

class WatchedTextures final : public cpu::TextureUnit {
public:
  WatchedTextures(const cpu::TextureUnit& inner, const ir::Program& program)
      : inner_(inner), program_(program) {}
  cpu::Vec4 sample(uint32_t stage, const cpu::Vec4& coord, float lod_bias) const override {
    if (first_.empty()) {
      const int n = addressed_components(program_, stage);
      bool finite = true;
      for (int c = 0; c < n; ++c) finite = finite && std::isfinite(coord[c]);
      if (!finite)
        first_ = n == 3 ? fmt::format("s{} at ({}, {}, {})", stage, show(coord[0]), show(coord[1]),
                                      show(coord[2]))
                        : fmt::format("s{} at ({}, {})", stage, show(coord[0]), show(coord[1]));
    }
    return inner_.sample(stage, coord, lod_bias);
  }
  cpu::StageState stage_state(uint32_t stage) const override { return inner_.stage_state(stage); }
  const std::string& first() const { return first_; }

private:
  const cpu::TextureUnit& inner_;
  const ir::Program& program_;
  mutable std::string first_;
};

} // namespace

std::string non_finite_read(const pass::Pass& pass) {
  if (!pass.pixel_program || pass.vertex_program || !pass.transformed.empty()) return "";
  ir::Result<cpu::ShaderVM> vm = cpu::ShaderVM::create(*pass.pixel_program, pass.conventions);
  if (!vm) return "";
  pass::PixelInput in = pass.constant_inputs;
  for (auto& colour : in.color) // as the draw feeds them (NUMERICS.md rule 26)
    for (float& v : colour) v = v > 0 ? (v < 1 ? v : 1) : 0;
  const cpu::BoundTextures bound(pass.textures, pass.conventions.subtexel_bits,
                                 pass.conventions.rounding == ir::Rounding::Llvmpipe);
  const WatchedTextures watched(bound, *pass.pixel_program);
  vm->run_pixel(in, pass.ps_constants, watched);
  return watched.first();
}

} // namespace tierlift::corpus
