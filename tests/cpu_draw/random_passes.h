// Shared by the draw tests: a pass of random perspective triangles with a shader that reads
// colours, coordinates and a texture, and kills some pixels.
#pragma once

#include <memory>
#include <random>

#include "draw_helpers.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/cpu/draw.h"

namespace tierlift::cpu::test {

// `vertices` / 3 triangles over a w×h target, partly off screen, of both windings, with
// w_clip in [0.5, 3) (perspective-correct inputs), colour v0 and coordinates t0, t1 in
// [-0.5, 1.5); the pixel shader modulates a bilinear read of a random 17×11 texture by v0,
// adds t1 and kills the pixels where t1 has a negative component. Partial blocks at every
// edge, killed lanes among written ones.
inline Pass random_perspective_pass(std::mt19937& rng, int vertices, uint32_t w, uint32_t h) {
  static const auto ps = std::make_shared<const ir::Program>(
      *assembly::parse_text("ps_2_0\ndcl v0\ndcl t0\ndcl t1\ndcl_2d s0\ntexld r0, t0, s0\n"
                            "mad r0, r0, v0, t1\ntexkill t1\nmov oC0, r0\n",
                            "<test>")
           .program);
  std::uniform_real_distribution<double> x(-20.0, w + 20.0), y(-20.0, h + 20.0);
  std::uniform_real_distribution<float> val(-0.5f, 1.5f), wclip(0.5f, 3.0f), texel(0.0f, 1.0f);
  Pass pass;
  pass.pixel_program = ps;
  for (int i = 0; i < vertices; ++i) {
    VertexOutput v = screen_vertex(x(rng), y(rng), w, h, wclip(rng));
    v.color[0] = {val(rng), val(rng), val(rng), val(rng)};
    v.tex[0] = {val(rng), val(rng), val(rng), val(rng)};
    v.tex[1] = {val(rng), val(rng), val(rng), val(rng)};
    pass.transformed.push_back(v);
  }
  auto tex = std::make_shared<img::Image>(17, 11, img::Format::RGBA32F);
  for (float& t : tex->rgba) t = texel(rng);
  pass.textures[0].image = tex;
  pass.textures[0].sampler.filter = Filter::Linear;
  return pass;
}

} // namespace tierlift::cpu::test
