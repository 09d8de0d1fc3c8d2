// draw_pass: one cpu::Pass on Vulkan — programs, vertex data, constants, sampled textures,
// descriptors, pipeline, the draw (see device.h for the mapping, pass_draw.h for the split).
#include "pass_draw.h"

#include <chrono>
#include <cstring>

#include <fmt/format.h>

#include "bindings.h"
#include "pipeline.h"
#include "synthetic_programs.h"

namespace tierlift::vulkan {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// The D3DVIEWPORT9 depth range is [0, 1]; Vulkan rejects values outside it without
// VK_EXT_depth_range_unrestricted.
float clamp01(float v) {
  return v > 0 ? (v < 1 ? v : 1) : 0;
}

constexpr uint32_t kVertexStride = 16 * 16; // sixteen vec4 input registers

struct Geometry {
  std::vector<std::array<cpu::Vec4, 16>> vertices;
  std::vector<uint32_t> indices;
};

// The vertex stream of the pass (see device.h): the pass's own vertices with a vertex
// program, otherwise the inputs of the pass-through vertex program.
std::string build_geometry(const cpu::Pass& pass, Geometry& g) {
  auto from_output = [](const cpu::VertexOutput& o) {
    std::array<cpu::Vec4, 16> v;
    v.fill({0, 0, 0, 1});
    v[kPassPosition] = o.pos;
    v[kPassColor] = o.color[0];
    v[kPassColor + 1] = o.color[1];
    for (uint32_t n = 0; n < 8; ++n) v[kPassTex + n] = o.tex[n];
    return v;
  };
  std::vector<std::array<uint32_t, 3>> tris = pass.triangles;
  if (pass.vertex_program) {
    for (const auto& in : pass.vertices) g.vertices.push_back(in.v);
  } else if (!pass.transformed.empty()) {
    for (const auto& o : pass.transformed) g.vertices.push_back(from_output(o));
  } else {
    cpu::VertexOutput o;
    o.color = pass.constant_inputs.color;
    o.tex = pass.constant_inputs.tex;
    for (const auto& corner : cpu::kQuadCorners) {
      o.pos = corner;
      g.vertices.push_back(from_output(o));
    }
    tris.assign(cpu::kQuadTriangles.begin(), cpu::kQuadTriangles.end());
  }
  if (tris.empty())
    for (uint32_t k = 0; k + 2 < g.vertices.size(); k += 3) tris.push_back({k, k + 1, k + 2});
  for (const auto& t : tris)
    for (uint32_t i : t) {
      if (i >= g.vertices.size())
        return fmt::format("triangle index {} out of range ({} vertices)", i, g.vertices.size());
      g.indices.push_back(i);
    }
  return {};
}

std::string join_diagnostics(const ir::DiagnosticSink& diags) {
  std::string out;
  for (const auto& dg : diags.all())
    if (dg.severity == ir::Severity::Error) out += (out.empty() ? "" : "; ") + dg.message;
  return out.empty() ? "code generation failed" : out;
}

// Textures made for this draw only: host images of stages without a resident texture, as
// the old per-pass path did (R32G32B32A32_SFLOAT, the floats as given).
struct Transients {
  std::vector<std::unique_ptr<Resident>> textures;
  std::vector<std::pair<Resident*, Buffer>> uploads;
};

std::string host_texture(Device::Impl& d, Cleanup& cleanup, uint32_t stage, const img::Image& im,
                         Transients& out, Resident*& r) {
  if (im.width == 0 || im.height == 0 || im.width > img::kMaxDimension ||
      im.height > img::kMaxDimension || im.rgba.size() != size_t{im.width} * im.height * 4)
    return fmt::format("s{}: texture has no pixels", stage);
  std::unique_ptr<Resident> t;
  Buffer staging;
  std::string err = create_resident(d, im.width, im.height, img::Format::RGBA32F, t);
  if (err.empty())
    err = create_buffer(d, cleanup, im.rgba.size() * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, staging);
  if (!err.empty()) return err;
  std::memcpy(staging.mapped, im.rgba.data(), im.rgba.size() * 4);
  r = t.get();
  out.uploads.emplace_back(r, staging);
  out.textures.push_back(std::move(t));
  return {};
}

// The layouts a failed submit must restore (recording already advanced them).
struct LayoutSnapshot {
  std::vector<std::pair<TrackedImage*, VkImageLayout>> saved;
  std::vector<std::pair<Resident*, bool>> shadows;
  void save(Resident& r) {
    saved.emplace_back(&r.stored, r.stored.layout);
    saved.emplace_back(&r.shadow, r.shadow.layout);
    shadows.emplace_back(&r, r.shadow_current);
  }
  void restore() {
    for (auto& [t, l] : saved) t->layout = l;
    for (auto& [r, s] : shadows) r->shadow_current = s;
  }
};

} // namespace

DrawResult draw_pass(Device::Impl& d, const cpu::Pass& pass, const DrawTextures& textures,
                     const DrawOptions& options) {
  DrawResult res;
  auto fail = [&](std::string msg) {
    res.ok = false;
    res.error = std::move(msg);
    return res;
  };
  const auto t0 = Clock::now();
  if (!textures.target) return fail("no render target");
  Resident& target = *textures.target;
  if (pass.vertex_program && pass.vertex_program->stage() != ir::ShaderStage::Vertex)
    return fail("the vertex program is not a vertex shader");
  if (pass.pixel_program && pass.pixel_program->stage() != ir::ShaderStage::Pixel)
    return fail("the pixel program is not a pixel shader");

  // Programs → SPIR-V.
  auto vs_prog = pass.vertex_program ? pass.vertex_program : passthrough_vertex_program();
  auto ps_prog = pass.pixel_program ? pass.pixel_program : passthrough_pixel_program();
  codegen::CodegenOptions co;
  co.conventions = pass.conventions;
  for (uint32_t s = 0; s < cpu::kMaxSamplers; ++s)
    co.stage_projected[s] = pass.textures[s].stage.projected;
  ir::DiagnosticSink diags;
  auto pair = codegen::compile_pair(*vs_prog, *ps_prog, co, diags);
  if (!pair) return fail(join_diagnostics(diags));
  if (!pair->vs.samplers.empty()) return fail("vertex-stage texture sampling is not supported");

  Geometry geo;
  if (std::string e = build_geometry(pass, geo); !e.empty()) return fail(e);

  Cleanup cleanup;
  std::string err;
  // The textures the pixel program samples: resident ones, else host images for this draw.
  Transients transients;
  std::array<Resident*, cpu::kMaxSamplers> sampled{};
  SampledImages images{};
  img::Image unbound(1, 1);
  unbound.rgba = {0, 0, 0, 1}; // an unbound stage reads (0, 0, 0, 1), as in D3D9
  for (const auto& si : pair->ps.samplers) {
    const uint32_t s = si.stage % cpu::kMaxSamplers;
    if (sampled[s]) continue;
    sampled[s] = textures.stages[s];
    if (sampled[s] == &target)
      return fail(fmt::format("s{}: a pass cannot sample its own render target", si.stage));
    if (!sampled[s]) {
      const img::Image& im = pass.textures[s].image ? *pass.textures[s].image : unbound;
      err = host_texture(d, cleanup, si.stage, im, transients, sampled[s]);
    }
    if (err.empty()) err = ensure_shadow(d, *sampled[s]);
    if (!err.empty()) return fail(err);
    images[s] = &sampled[s]->sampled();
  }

  // Vertex and index buffers.
  Buffer vbuf, ibuf;
  err = create_buffer(d, cleanup, geo.vertices.size() * kVertexStride,
                      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vbuf);
  if (err.empty())
    err = create_buffer(d, cleanup, geo.indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, ibuf);
  if (!err.empty()) return fail(err);
  if (!geo.vertices.empty())
    std::memcpy(vbuf.mapped, geo.vertices.data(), geo.vertices.size() * kVertexStride);
  if (!geo.indices.empty()) std::memcpy(ibuf.mapped, geo.indices.data(), geo.indices.size() * 4);

  // Descriptor set 0 and the pipeline layout.
  Bindings bound;
  err = create_bindings(d, cleanup, *pair, pass, images, bound);
  if (!err.empty()) return fail(err);

  // Render pass, pipeline, and the staging buffer of a host target (upload, then readback).
  const VkFormat rt_format = target.stored.image.format;
  VkFormatProperties rt_props;
  vkGetPhysicalDeviceFormatProperties(d.physical, rt_format, &rt_props);
  if (!(rt_props.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT) ||
      (pass.blend != cpu::BlendMode::Replace &&
       !(rt_props.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT)))
    return fail(fmt::format("the Vulkan device cannot render (and blend) to {}",
                            img::format_name(target.format)));
  Buffer rt_staging;
  if (textures.host_target) {
    const VkDeviceSize rt_bytes =
        VkDeviceSize{target.width} * target.height * bytes_per_pixel(target.format);
    err = create_buffer(d, cleanup, rt_bytes,
                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        rt_staging);
    if (!err.empty()) return fail(err);
    pack_pixels(*textures.host_target, rt_staging.mapped);
    transients.uploads.emplace_back(&target, rt_staging);
  }
  VkRenderPass rp = VK_NULL_HANDLE;
  VkFramebuffer fb = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  err = create_render_pass(d, cleanup, rt_format, rp);
  if (err.empty()) err = create_framebuffer(d, cleanup, rp, target.stored.image, fb);
  PipelineDesc pd;
  pd.vs = &pair->vs;
  pd.ps = &pair->ps;
  pd.ps_words = options.flat_varyings ? decorate_inputs_flat(pair->ps.words) : pair->ps.words;
  pd.blend = pass.blend;
  pd.render_pass = rp;
  pd.layout = bound.layout;
  pd.vertex_stride = kVertexStride;
  if (err.empty()) err = create_pipeline(d, cleanup, pd, pipeline);
  if (!err.empty()) return fail(err);

  // Host data (the old path's textures and target) goes up first, in its own submit.
  LayoutSnapshot snapshot;
  snapshot.save(target);
  for (Resident* r : sampled)
    if (r) snapshot.save(*r);
  if (!transients.uploads.empty()) {
    err = submit_and_wait(d, [&](VkCommandBuffer cb) {
      for (auto& [r, staging] : transients.uploads) record_upload(cb, *r, staging.buffer);
    });
    if (!err.empty()) {
      snapshot.restore();
      return fail(err);
    }
  }

  // Viewport (D3D9 centres: +0.5 pixel) and scissor (the D3D9 viewport within the target).
  const cpu::Viewport& v = pass.viewport;
  const uint32_t vw = v.width ? v.width : target.width, vh = v.height ? v.height : target.height;
  const float shift = pass.conventions.pixel_center == ir::PixelCenter::D3D9 ? 0.5f : 0.0f;
  VkViewport viewport{static_cast<float>(v.x) + shift,
                      static_cast<float>(v.y) + shift,
                      static_cast<float>(vw),
                      static_cast<float>(vh),
                      clamp01(v.min_z),
                      clamp01(v.max_z)};
  int64_t sx0 = std::max<int64_t>(v.x, 0), sy0 = std::max<int64_t>(v.y, 0);
  int64_t sx1 = std::min<int64_t>(int64_t{v.x} + vw, target.width);
  int64_t sy1 = std::min<int64_t>(int64_t{v.y} + vh, target.height);
  const bool visible = sx1 > sx0 && sy1 > sy0 && !geo.indices.empty();
  VkRect2D scissor{
      {static_cast<int32_t>(visible ? sx0 : 0), static_cast<int32_t>(visible ? sy0 : 0)},
      {static_cast<uint32_t>(visible ? sx1 - sx0 : 1),
       static_cast<uint32_t>(visible ? sy1 - sy0 : 1)}};
  res.setup_ms = ms_since(t0);

  const auto t1 = Clock::now();
  err = submit_and_wait(d, [&](VkCommandBuffer cb) {
    for (Resident* r : sampled)
      if (r) record_as_sampled(cb, d, *r);
    record_as_target(cb, target);
    VkRenderPassBeginInfo rbi{};
    rbi.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    rbi.renderPass = rp;
    rbi.framebuffer = fb;
    rbi.renderArea = {{0, 0}, {target.width, target.height}};
    vkCmdBeginRenderPass(cb, &rbi, VK_SUBPASS_CONTENTS_INLINE);
    if (visible) {
      vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, bound.layout, 0, 1, &bound.set,
                              0, nullptr);
      VkDeviceSize offset = 0;
      vkCmdBindVertexBuffers(cb, 0, 1, &vbuf.buffer, &offset);
      vkCmdBindIndexBuffer(cb, ibuf.buffer, 0, VK_INDEX_TYPE_UINT32);
      vkCmdSetViewport(cb, 0, 1, &viewport);
      vkCmdSetScissor(cb, 0, 1, &scissor);
      vkCmdDrawIndexed(cb, static_cast<uint32_t>(geo.indices.size()), 1, 0, 0, 0);
    }
    vkCmdEndRenderPass(cb);
    if (textures.host_target) record_readback(cb, target, rt_staging.buffer);
  });
  if (!err.empty()) {
    snapshot.restore();
    return fail(err);
  }
  res.draw_ms = ms_since(t1);
  if (textures.host_target) unpack_pixels(rt_staging.mapped, *textures.host_target);
  res.ok = true;
  return res;
}

} // namespace tierlift::vulkan
