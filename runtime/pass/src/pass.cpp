// The quad's inputs and the capability check shared by every device.
#include "tierlift/pass/pass.h"

#include <fmt/format.h>

#include "tierlift/ir/profile.h"
#include "tierlift/ir/sm3_interface.h"

namespace tierlift::pass {

ir::Status check_supported(const Pass& pass, const Capabilities& caps, std::string_view device) {
  auto refuse = [&](std::string what) {
    return ir::fail(std::string(device), "unsupported",
                    fmt::format("the {} device cannot draw {} yet", device, what));
  };
  if (pass.color_targets == 0) return refuse("a pass without a colour target");
  if (pass.color_targets > caps.max_color_targets)
    return refuse(fmt::format("into {} render targets (at most {})", pass.color_targets,
                              caps.max_color_targets));
  if (pass.depth_stencil.enabled() && !caps.depth_stencil)
    return refuse("with a depth/stencil buffer");
  if (pass.pixel_spirv && !caps.spirv_pixel_stage)
    return refuse("a pixel stage given as SPIR-V (GLSL)");
  if (pass.pixel_spirv && !pass.pixel_program)
    return ir::fail(std::string(device), "pass",
                    "a SPIR-V pixel stage needs its ps_2_0 twin (the interface it follows)");
  // ps_1_x reads take no lod on the interpreter (no quads for its texture-address
  // instructions): a mip chain read by lod is refused there (NUMERICS.md M5).
  if (pass.pixel_program && !ir::is_sm2_or_later(pass.pixel_program->profile))
    for (uint32_t s = 0; s < kMaxSamplers; ++s)
      if (reads_by_lod(pass.textures[s]))
        return refuse(fmt::format("s{}'s mip chain with MIPFILTER POINT or LINEAR under a ps_1_x "
                                  "pixel shader",
                                  s));
  // Both devices run each stage on the 2.0 interface; a pair whose semantics would land in
  // different slots there cannot link (ir::check_semantic_pair).
  if (pass.vertex_program && pass.pixel_program)
    if (ir::Status s = ir::check_semantic_pair(*pass.vertex_program, *pass.pixel_program); !s)
      return ir::fail(std::string(device), "unsupported",
                      fmt::format("the {} device cannot draw this pair: {}", device, s.message()));
  return ir::ok_status();
}

std::optional<ir::Program> fed_vertex_program(const Pass& pass) {
  if (!pass.vertex_program || !pass.pixel_program || !ir::fog_slot(*pass.pixel_program))
    return std::nullopt;
  return ir::feed_fog(*pass.vertex_program, *pass.pixel_program);
}

bool reads_mips_by_lod(const Pass& pass) {
  for (const TextureBinding& b : pass.textures)
    if (reads_by_lod(b)) return true;
  return false;
}

TextureBinding* sampler_binding(Pass& pass, uint32_t stage) {
  if (stage < kMaxSamplers) return &pass.textures[stage];
  return is_vertex_sampler(stage) ? &pass.vertex_textures[stage - kVertexSampler0] : nullptr;
}

const TextureBinding* sampler_binding(const Pass& pass, uint32_t stage) {
  if (stage < kMaxSamplers) return &pass.textures[stage];
  return is_vertex_sampler(stage) ? &pass.vertex_textures[stage - kVertexSampler0] : nullptr;
}

uint32_t position_input(const ir::Program& vertex_program) {
  for (const ir::Declaration& d : vertex_program.decls)
    if (d.reg.file == ir::RegFile::Input && d.usage == ir::DeclUsage::Position &&
        d.usage_index == 0)
      return d.reg.index;
  return 0;
}

std::vector<uint32_t> texcoord_inputs(const ir::Program& vertex_program) {
  std::vector<uint32_t> out;
  for (const ir::Declaration& d : vertex_program.decls)
    if (d.reg.file == ir::RegFile::Input && d.usage == ir::DeclUsage::TexCoord && d.reg.index < 16)
      out.push_back(d.reg.index);
  return out;
}

void set_full_screen_quad(Pass& pass, uint32_t position_register) {
  pass.vertices.assign(4, VertexInput{});
  for (size_t i = 0; i < 4; ++i)
    if (position_register < 16) pass.vertices[i].v[position_register] = kQuadCorners[i];
  pass.triangles.assign(kQuadTriangles.begin(), kQuadTriangles.end());
}

void set_full_screen_quad_uv(Pass& pass) {
  const uint32_t position = position_input(*pass.vertex_program);
  set_full_screen_quad(pass, position);
  for (uint32_t reg : texcoord_inputs(*pass.vertex_program))
    if (reg != position)
      for (size_t c = 0; c < 4; ++c) pass.vertices[c].v[reg] = kQuadUV[c];
}

} // namespace tierlift::pass
