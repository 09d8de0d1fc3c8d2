// The textures a draw's pixel program samples: resident ones, or the pass's host images,
// cube and volume layers (or the unbound texture) uploaded for this draw (sampled_textures.h).
#include "sampled_textures.h"

#include <cstring>

#include <fmt/format.h>

#include "tierlift/pass/srgb.h"

namespace tierlift::vulkan {
namespace {

// A host image of a stage without a resident texture, as the old per-pass path did
// (R32G32B32A32_SFLOAT, the floats as given), uploaded now: it belongs to the draw.
ir::Status host_texture(Device::Impl& d, uint32_t stage, const img::Image& im, PreparedDraw& out,
                        Resident*& r) {
  if (im.width == 0 || im.height == 0 || im.width > img::kMaxDimension ||
      im.height > img::kMaxDimension || im.rgba.size() != size_t{im.width} * im.height * 4)
    return draw_failure(fmt::format("s{}: texture has no pixels", stage));
  std::unique_ptr<Resident> t;
  Cleanup staging_objects;
  Buffer staging;
  ir::Status err = create_resident(d, im.width, im.height, img::Format::RGBA32F, t);
  if (err)
    err = create_buffer(d, staging_objects, im.rgba.size() * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                        staging);
  if (!err) return err;
  std::memcpy(staging.mapped, im.rgba.data(), im.rgba.size() * 4);
  err = submit_and_wait(d, [&](VkCommandBuffer cb) { record_upload(cb, *t, staging.buffer); });
  if (!err) return err;
  r = t.get();
  out.host_textures.push_back(std::move(t));
  return ir::ok_status();
}

// A cube or volume texture of the pass (or the unbound one of that type, reading (0, 0, 0, 1)
// as in D3D9), uploaded now: it belongs to the draw. Resident textures are 2D, so a cube or
// volume sampler reads the binding's host layers (in an effect graph the device binds images
// by texture id, and the layers ride with the binding, effects::TextureBind). `bound` says
// whether the stage has a texture at all (a resident one, or the pass's image).
ir::Status host_layered_texture(Device::Impl& d, const codegen::SamplerInfo& si,
                                const pass::TextureBinding& b, bool bound, PreparedDraw& out,
                                Resident*& r) {
  const pass::TextureShape want =
      si.type == ir::SamplerType::Cube ? pass::TextureShape::Cube : pass::TextureShape::Volume;
  std::vector<std::shared_ptr<const img::Image>> layers = b.layers;
  if (bound && (b.shape != want || layers.empty())) {
    const char* name = want == pass::TextureShape::Cube ? "cube" : "volume";
    return draw_failure(fmt::format("s{}: a {} sampler needs a {} texture", si.stage, name, name));
  }
  if (!bound) {
    auto texel = std::make_shared<img::Image>(1, 1);
    texel->rgba = {0, 0, 0, 1};
    layers.assign(want == pass::TextureShape::Cube ? 6 : 1, texel);
  }
  const img::Image& first = *layers[0];
  std::unique_ptr<Resident> t;
  Cleanup staging_objects;
  Buffer staging;
  const size_t floats = first.rgba.size();
  ir::Status err = create_layered_resident(d, first.width, first.height, want,
                                           static_cast<uint32_t>(layers.size()), t);
  if (err)
    err = create_buffer(d, staging_objects, floats * layers.size() * 4,
                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT, staging);
  if (!err) return err;
  for (size_t k = 0; k < layers.size(); ++k)
    std::memcpy(static_cast<float*>(staging.mapped) + k * floats, layers[k]->rgba.data(),
                floats * 4);
  err = submit_and_wait(d, [&](VkCommandBuffer cb) { record_upload(cb, *t, staging.buffer); });
  if (!err) return err;
  r = t.get();
  out.host_textures.push_back(std::move(t));
  return ir::ok_status();
}

} // namespace

// A 2D binding's mip chain (pass::TextureBinding::levels, RGBA32F, level 0 first), uploaded
// now: it belongs to the draw. Resident textures have one level, so a stage with levels
// reads the binding's host levels.
ir::Status host_mip_texture(Device::Impl& d, const pass::TextureBinding& b, PreparedDraw& out,
                            Resident*& r) {
  const img::Image& base = *b.levels[0];
  size_t floats = 0;
  for (const auto& level : b.levels) floats += level->rgba.size();
  std::unique_ptr<Resident> t;
  Cleanup staging_objects;
  Buffer staging;
  ir::Status err =
      create_mip_resident(d, base.width, base.height, static_cast<uint32_t>(b.levels.size()), t);
  if (err)
    err = create_buffer(d, staging_objects, floats * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, staging);
  if (!err) return err;
  size_t at = 0;
  for (const auto& level : b.levels) {
    std::memcpy(static_cast<float*>(staging.mapped) + at, level->rgba.data(),
                level->rgba.size() * 4);
    at += level->rgba.size();
  }
  err = submit_and_wait(d, [&](VkCommandBuffer cb) { record_upload(cb, *t, staging.buffer); });
  if (!err) return err;
  r = t.get();
  out.host_textures.push_back(std::move(t));
  return ir::ok_status();
}

namespace {

// One sampler of either stage (`name` as messages show it: "s2", "vertex s0"), bound at
// `slot`: its resident texture, else the binding's host image (or the unbound texture)
// uploaded for this draw.
ir::Status bind_one(Device::Impl& d, const pass::TextureBinding& raw, const DrawTextures& textures,
                    const codegen::SamplerInfo& si, const std::string& name, uint32_t slot,
                    PreparedDraw& out, SampledImages& images) {
  Resident*& r = out.sampled[slot];
  if (r) return ir::ok_status();
  r = textures.stages[slot];
  bool own = r && r == textures.target;
  for (const Resident* m : textures.more_targets) own = own || (r && r == m);
  if (own) return draw_failure(fmt::format("{}: a pass cannot sample its own render target", name));
  ir::Status err = ir::ok_status();
  // An sRGB stage reads its texels decoded before filtering (NUMERICS.md S1, S2), which
  // this device does on the host (pass/srgb.h): a texture that lives on the device only
  // (one an earlier pass rendered) has no host image to decode.
  const pass::TextureBinding binding = pass::srgb_resolved(raw);
  if (r && raw.sampler.srgb)
    return draw_failure(fmt::format("{}: an sRGB read (SRGBTEXTURE) of a texture the device "
                                    "rendered is not supported: only images given to the "
                                    "pass are decoded",
                                    name));
  img::Image unbound(1, 1);
  unbound.rgba = {0, 0, 0, 1}; // an unbound stage reads (0, 0, 0, 1), as in D3D9
  if (si.type == ir::SamplerType::Cube || si.type == ir::SamplerType::Volume) {
    // The binding's layers, uploaded with the draw (a resident texture is 2D: in an effect
    // graph it holds the first layer only, effects::TextureBind).
    const bool bound = r || binding.image || !binding.layers.empty();
    r = nullptr;
    err = host_layered_texture(d, si, binding, bound, out, r);
  } else if (binding.shape != pass::TextureShape::Tex2D) {
    err = draw_failure(fmt::format("{}: a 2D sampler cannot read a cube or volume texture", name));
  } else if (raw.levels.size() > 1) {
    r = nullptr; // the binding's levels, uploaded with the draw
    err = host_mip_texture(d, raw, out, r);
  } else if (!r) {
    const img::Image& im = binding.image ? *binding.image : unbound;
    err = host_texture(d, si.stage, im, out, r);
  }
  out.fetched[slot] = si.fetch_unorm8;
  if (err && !si.fetch_unorm8) err = ensure_shadow(d, *r);
  if (!err) return err;
  images[slot] = si.fetch_unorm8 ? &r->stored.image : &r->sampled();
  return ir::ok_status();
}

} // namespace

// The textures the programs sample: the pixel program's s#, then the vertex program's (vs_3_0
// texldl: the pass's vertex samplers, NUMERICS.md F14).
ir::Status bind_sampled(Device::Impl& d, const pass::Pass& pass, const DrawTextures& textures,
                        const codegen::CompiledPair& pair, PreparedDraw& out,
                        SampledImages& images) {
  for (const auto& si : pair.ps.samplers) {
    const uint32_t s = si.stage % pass::kMaxSamplers;
    if (ir::Status e = bind_one(d, pass.textures[s], textures, si, fmt::format("s{}", si.stage), s,
                                out, images);
        !e)
      return e;
  }
  for (const auto& si : pair.vs.samplers) {
    const std::string name = fmt::format("vertex s{}", si.stage);
    const pass::TextureBinding* b = pass::sampler_binding(pass, pass::kVertexSampler0 + si.stage);
    if (!b) return draw_failure(fmt::format("{}: the vertex stage has s0..s3 only", name));
    const uint32_t slot = pass::sampler_slot(pass::kVertexSampler0 + si.stage);
    if (ir::Status e = bind_one(d, *b, textures, si, name, slot, out, images); !e) return e;
  }
  return ir::ok_status();
}

} // namespace tierlift::vulkan
