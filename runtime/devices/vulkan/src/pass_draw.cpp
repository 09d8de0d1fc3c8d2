// prepare_draw / record_draw / draw_pass: one pass::Pass on Vulkan — programs, vertex data,
// constants, sampled textures, descriptors, pipeline, the draw (see device.h for the
// mapping, pass_draw.h for the split).
#include "pass_draw.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include <fmt/format.h>

#include "bindings.h"
#include "pipeline.h"
#include "program_reuse.h"
#include "sampled_textures.h"
#include "synthetic_programs.h"
#include "tierlift/ir/device_pipeline.h"
#include "tierlift/pass/depth.h"

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
  std::vector<std::array<pass::Vec4, 16>> vertices;
  std::vector<uint32_t> indices;
};

// The vertex stream of the pass (see device.h): the pass's own vertices with a vertex
// program, otherwise the inputs of the pass-through vertex program.
ir::Status build_geometry(const pass::Pass& pass, Geometry& g) {
  auto from_output = [](const pass::VertexOutput& o) {
    std::array<pass::Vec4, 16> v;
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
    pass::VertexOutput o;
    o.color = pass.constant_inputs.color;
    o.tex = pass.constant_inputs.tex;
    for (const auto& corner : pass::kQuadCorners) {
      o.pos = corner;
      g.vertices.push_back(from_output(o));
    }
    tris.assign(pass::kQuadTriangles.begin(), pass::kQuadTriangles.end());
  }
  if (tris.empty())
    for (uint32_t k = 0; k + 2 < g.vertices.size(); k += 3) tris.push_back({k, k + 1, k + 2});
  for (const auto& t : tris)
    for (uint32_t i : t) {
      if (i >= g.vertices.size())
        return draw_failure(
            fmt::format("triangle index {} out of range ({} vertices)", i, g.vertices.size()));
      g.indices.push_back(i);
    }
  return ir::ok_status();
}

std::string join_diagnostics(const ir::DiagnosticSink& diags) {
  std::string out;
  for (const auto& dg : diags.all())
    if (dg.severity == ir::Severity::Error) out += (out.empty() ? "" : "; ") + dg.message;
  return out.empty() ? "code generation failed" : out;
}

// Whether a stage's reads fetch the stored RGBA8 bytes in place instead of sampling a float
// shadow (codegen::CodegenOptions::stage_fetch_unorm8): a resident RGBA8 colour texture read
// with POINT filtering and CLAMP addressing on both axes. The fetch reproduces point
// sampling's texel and the shadow's exact k/255.0f, so the image is the same; what it saves is
// the shadow's conversion each time the texture changed.
bool fetches_in_place(const Device::Impl& d, const Resident* r, const pass::SamplerState& s) {
  return d.unorm8_in_place && r && !r->depth_stencil() && r->format == img::Format::RGBA8 &&
         pass::point_clamped(s);
}

// The layouts a failed submit must restore (recording already advanced them).
struct LayoutSnapshot {
  std::vector<std::pair<TrackedImage*, VkImageLayout>> saved;
  std::vector<std::pair<Resident*, bool>> shadows;
  void save(Resident& r) {
    saved.emplace_back(&r.stored, r.stored.layout);
    if (r.shadow) save(*r.shadow); // its layout, and the draw that fills it changes it
    shadows.emplace_back(&r, r.shadow_current);
  }
  void restore() {
    for (auto& [t, l] : saved) t->layout = l;
    for (auto& [r, s] : shadows) r->shadow_current = s;
  }
};

// Every oC# below pass.color_targets must be an output of the pixel stage: Vulkan leaves an
// attachment without a fragment output undefined (D3D9's validator already requires oC0..
// oC(n-1) to be written when oCn is; here the pass may name more targets than it writes).
ir::Status check_color_outputs(const pass::Pass& pass, const codegen::ShaderModule& ps) {
  for (uint32_t i = 1; i < pass.color_targets; ++i) {
    bool written = false;
    for (const auto& iv : ps.interface)
      written = written || (iv.kind == codegen::InterfaceKind::Output && iv.location == i);
    if (!written)
      return draw_failure(
          fmt::format("the pass draws into {} render targets, but its pixel program does not "
                      "write oC{}",
                      pass.color_targets, i));
  }
  return ir::ok_status();
}

// The targets beyond oC0 and the stencil buffer: bound as the pass asks, each the size of
// oC0, none of them twice.
ir::Status check_targets(const pass::Pass& pass, const DrawTextures& t) {
  const Resident& first = *t.target;
  std::vector<const Resident*> seen{&first};
  for (uint32_t i = 1; i < 4; ++i) {
    const Resident* r = t.more_targets[i - 1];
    if (i >= pass.color_targets) {
      if (r)
        return draw_failure(fmt::format("render target {} is bound, but the pass draws into {}", i,
                                        pass.color_targets));
      continue;
    }
    if (!r) return draw_failure(fmt::format("render target {} (oC{}) is not bound", i, i));
    if (r->depth_stencil())
      return draw_failure(fmt::format("render target {} is a depth or stencil buffer", i));
    if (r->width != first.width || r->height != first.height)
      return draw_failure(
          fmt::format("render target {} is {}x{}, render target 0 is {}x{}: every target of "
                      "a pass has one size",
                      i, r->width, r->height, first.width, first.height));
    for (const Resident* s : seen)
      if (s == r) return draw_failure(fmt::format("render target {} is bound twice", i));
    seen.push_back(r);
  }
  const pass::DepthStencilState& ds = pass.depth_stencil;
  if (pass::uses_depth(ds) && !t.depth)
    return draw_failure("the pass has a depth state but no depth buffer is bound");
  if (pass::uses_depth(ds) && (ds.stencil_test || t.stencil))
    return draw_failure("a depth buffer and a stencil buffer in one pass are not drawn yet");
  if (t.depth && !pass::uses_depth(ds))
    return draw_failure("a depth buffer is bound, but the pass has no depth state");
  if (t.depth) {
    if (!t.depth->depth) return draw_failure("the depth buffer is not a depth texture");
    if (t.depth->width != first.width || t.depth->height != first.height)
      return draw_failure(fmt::format("the depth buffer is {}x{}, the render target {}x{}",
                                      t.depth->width, t.depth->height, first.width, first.height));
  }
  if (ds.stencil_test && !t.stencil)
    return draw_failure("the pass has a stencil test but no stencil buffer is bound");
  if (t.stencil) {
    if (!t.stencil->stencil) return draw_failure("the stencil buffer is a colour texture");
    if (t.stencil->width != first.width || t.stencil->height != first.height)
      return draw_failure(fmt::format("the stencil buffer is {}x{}, the render target {}x{}",
                                      t.stencil->width, t.stencil->height, first.width,
                                      first.height));
  }
  if (first.depth_stencil()) return draw_failure("render target 0 is a depth or stencil buffer");
  return ir::ok_status();
}

// The traced module's record (codegen::TracePixel's layout) out of its storage buffer.
void read_trace(const PreparedDraw& p, ShaderTrace& out) {
  const codegen::TraceInfo& info = *p.trace_info;
  out.points = info.points;
  out.value.assign(info.entries, {0, 0, 0, 0});
  out.hits.assign(info.entries, 0);
  const auto* bytes = static_cast<const unsigned char*>(p.trace.mapped);
  for (uint32_t i = 0; i < info.entries; ++i) {
    const unsigned char* entry = bytes + size_t{i} * codegen::kTraceEntryBytes;
    std::memcpy(out.value[i].data(), entry, 16);
    std::memcpy(&out.hits[i], entry + 16, 4);
  }
}

} // namespace

namespace {

// The programs as SPIR-V, compiled for the pass's constants and the device's read paths.
ir::Status compile_programs(const Device::Impl& d, const pass::Pass& pass,
                            const DrawTextures& textures,
                            std::optional<codegen::CompiledPair>& out) {
  auto vs_prog = pass.vertex_program ? pass.vertex_program : passthrough_vertex_program();
  auto ps_prog = pass.pixel_program ? pass.pixel_program : passthrough_pixel_program();
  // Products with a ±0 constant factor read nothing else (ir::zero_constant_products), so
  // the code generator's pruning drops the texture reads and varyings that only fed them.
  // The draw is prepared (and cached, draw_cache.h) for these constants. Not for a GLSL pass:
  // its own SPIR-V needs the interface of the whole twin.
  // Reused programs (program_reuse.h) serve every set of constants: not specialised.
  // Otherwise the device pipeline (ir/device_pipeline.h); the emitter prunes.
  const bool for_these_constants = !textures.reuse || textures.trace;
  if (!pass.pixel_spirv && for_these_constants) {
    auto p = ir::prepare_for_device(*ps_prog, pass.ps_constants.f, {.drop_dead = false});
    if (!p) return draw_failure(p.message());
    if (p->specialised) ps_prog = std::make_shared<const ir::Program>(std::move(*p->specialised));
  }
  codegen::CodegenOptions co;
  co.conventions = pass.conventions;
  if (for_these_constants) {
    co.known_vs_constants = pass.vs_constants.f; // the draw is cached under them
    co.known_ps_constants = pass.ps_constants.f;
  } else {
    co.defs_in_block = true; // NUMERICS.md, "Lavapipe workarounds"
  }
  co.point_sampling_floors = d.point_sampling_floors;
  if (textures.trace) {
    if (!d.fragment_stores)
      return draw_failure("the Vulkan device cannot write a buffer from a pixel shader "
                          "(fragmentStoresAndAtomics), which tracing a pixel needs");
    co.trace = *textures.trace;
  }
  co.unorm8_decode = d.unorm8_decode;
  for (uint32_t s = 0; s < pass::kMaxSamplers; ++s) {
    // ps_1_x declares no sampler types: the bound texture's shape is the stage's type.
    const pass::TextureShape shape = pass.textures[s].shape;
    co.stage_texture_type[s] = shape == pass::TextureShape::Cube     ? ir::SamplerType::Cube
                               : shape == pass::TextureShape::Volume ? ir::SamplerType::Volume
                                                                     : ir::SamplerType::Unknown;
    co.stage_projected[s] = pass.textures[s].stage.projected;
    co.stage_fetch_unorm8[s] = fetches_in_place(d, textures.stages[s], pass.textures[s].sampler);
    co.stage_point_clamped[s] = pass::point_clamped(pass.textures[s].sampler);
  }
  for (uint32_t s = 0; s < pass::kMaxVertexSamplers; ++s)
    co.vertex_point_clamped[s] = pass::point_clamped(pass.vertex_textures[s].sampler);
  // D3DRS_SRGBWRITEENABLE: the module encodes the outputs of RGBA8 targets (NUMERICS.md S3).
  for (uint32_t i = 0; i < pass.color_targets && i < co.srgb_write.size(); ++i) {
    const Resident* t = i == 0 ? textures.target : textures.more_targets[i - 1];
    co.srgb_write[i] = pass.srgb_write && t && t->format == img::Format::RGBA8;
  }
  // The device's pass-through programs are new objects each time: keyed as null.
  const std::optional<std::string> key =
      textures.reuse && !pass.pixel_spirv
          ? compile_key(pass.vertex_program.get(), pass.pixel_program.get(), co)
          : std::nullopt;
  if (key)
    if (const codegen::CompiledPair* kept = textures.reuse->find_compiled(*key)) out = *kept;
  if (!out) {
    ir::DiagnosticSink diags;
    out = codegen::compile_pair(*vs_prog, *ps_prog, co, diags);
    if (!out) return draw_failure(join_diagnostics(diags));
    if (key) textures.reuse->keep_compiled(*key, pass.vertex_program, pass.pixel_program, *out);
  }
  return check_color_outputs(pass, out->ps);
}

// The vertex and index buffers, filled.
ir::Status upload_geometry(Device::Impl& d, const Geometry& geo, PreparedDraw& out) {
  ir::Status err = create_buffer(d, out.objects, geo.vertices.size() * kVertexStride,
                                 VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, out.vertices);
  if (err)
    err = create_buffer(d, out.objects, geo.indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                        out.indices);
  if (!err) return err;
  if (!geo.vertices.empty())
    std::memcpy(out.vertices.mapped, geo.vertices.data(), geo.vertices.size() * kVertexStride);
  if (!geo.indices.empty())
    std::memcpy(out.indices.mapped, geo.indices.data(), geo.indices.size() * 4);
  out.index_count = static_cast<uint32_t>(geo.indices.size());
  return ir::ok_status();
}

// The render pass over the targets (and the stencil buffer), its framebuffer and the
// pipeline.
ir::Status create_render_objects(Device::Impl& d, const pass::Pass& pass,
                                 const DrawTextures& textures, const codegen::CompiledPair& pair,
                                 VkPipelineLayout layout,
                                 const std::vector<VkDescriptorSetLayoutBinding>& layout_bindings,
                                 PreparedDraw& out) {
  std::vector<VkFormat> formats;
  std::vector<const Image2D*> attachments;
  for (uint32_t i = 0; i < pass.color_targets; ++i) {
    const Resident& t = i == 0 ? *textures.target : *textures.more_targets[i - 1];
    const VkFormat rt_format = t.stored.image.format;
    VkFormatProperties rt_props;
    vkGetPhysicalDeviceFormatProperties(d.physical, rt_format, &rt_props);
    if (!(rt_props.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT) ||
        (pass.blend != pass::BlendMode::Replace &&
         !(rt_props.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT)))
      return draw_failure(fmt::format("the Vulkan device cannot render (and blend) to {}",
                                      img::format_name(t.format)));
    formats.push_back(rt_format);
    attachments.push_back(&t.stored.image);
  }
  // The depth/stencil attachment: the stencil buffer or the depth buffer (check_targets
  // refuses both at once).
  const Resident* ds = textures.stencil ? textures.stencil : textures.depth;
  if (ds) attachments.push_back(&ds->stored.image);
  const VkFormat ds_format = ds ? ds->stored.image.format : VK_FORMAT_UNDEFINED;
  ir::Status err = create_render_pass(d, out.objects, formats, ds_format, out.render_pass);
  if (err) err = create_framebuffer(d, out.objects, out.render_pass, attachments, out.framebuffer);
  if (!err) return err;
  PipelineDesc pd;
  pd.vs = &pair.vs;
  pd.ps = &pair.ps;
  // A GLSL pass draws its own SPIR-V; the twin's module gave the interface (samplers,
  // constant block) the descriptors follow, and glslang names its entry point "main" as
  // codegen does.
  pd.ps_words = pass.pixel_spirv ? *pass.pixel_spirv : pair.ps.words;
  pd.blend = pass.blend;
  pd.front_face = pass.front_face;
  pd.color_targets = pass.color_targets;
  pd.stencil_attachment = ds != nullptr;
  pd.depth_stencil = pass.depth_stencil;
  pd.render_pass = out.render_pass;
  pd.layout = layout;
  pd.vertex_stride = kVertexStride;
  if (textures.reuse && !textures.trace)
    return textures.reuse->pipeline(d, pd, formats, ds_format, layout_bindings, out.pipeline);
  return create_pipeline(d, out.objects, pd, out.pipeline);
}

// Viewport (D3D9 centres: +0.5 pixel) and scissor (the D3D9 viewport within the target, and
// within the pass's scissor rectangle when it has one); whether anything is left to draw.
void place_viewport(const pass::Pass& pass, const Resident& target, bool has_triangles,
                    PreparedDraw& out) {
  const pass::Viewport& v = pass.viewport;
  const uint32_t vw = v.width ? v.width : target.width, vh = v.height ? v.height : target.height;
  const float shift = pass.conventions.pixel_center == ir::PixelCenter::D3D9 ? 0.5f : 0.0f;
  out.viewport = {static_cast<float>(v.x) + shift,
                  static_cast<float>(v.y) + shift,
                  static_cast<float>(vw),
                  static_cast<float>(vh),
                  clamp01(v.min_z),
                  clamp01(v.max_z)};
  int64_t sx0 = std::max<int64_t>(v.x, 0), sy0 = std::max<int64_t>(v.y, 0);
  int64_t sx1 = std::min<int64_t>(int64_t{v.x} + vw, target.width);
  int64_t sy1 = std::min<int64_t>(int64_t{v.y} + vh, target.height);
  if (pass.scissor) {
    sx0 = std::max<int64_t>(sx0, pass.scissor->x0);
    sy0 = std::max<int64_t>(sy0, pass.scissor->y0);
    sx1 = std::min<int64_t>(sx1, pass.scissor->x1);
    sy1 = std::min<int64_t>(sy1, pass.scissor->y1);
  }
  out.visible = sx1 > sx0 && sy1 > sy0 && has_triangles;
  out.scissor = {
      {static_cast<int32_t>(out.visible ? sx0 : 0), static_cast<int32_t>(out.visible ? sy0 : 0)},
      {static_cast<uint32_t>(out.visible ? sx1 - sx0 : 1),
       static_cast<uint32_t>(out.visible ? sy1 - sy0 : 1)}};
}

} // namespace

ir::Status prepare_draw(Device::Impl& d, const pass::Pass& pass, const DrawTextures& textures,
                        PreparedDraw& out) {
  if (!textures.target) return draw_failure("no render target");
  out.target = textures.target;
  out.more_targets = textures.more_targets;
  out.stencil = textures.stencil ? textures.stencil : textures.depth;
  if (pass.vertex_program && pass.vertex_program->stage() != ir::ShaderStage::Vertex)
    return draw_failure("the vertex program is not a vertex shader");
  if (pass.pixel_program && pass.pixel_program->stage() != ir::ShaderStage::Pixel)
    return draw_failure("the pixel program is not a pixel shader");
  if (ir::Status s = pass::check_supported(pass, kCapabilities, "vulkan"); !s)
    return draw_failure(s.message());
  if (ir::Status e = check_targets(pass, textures); !e) return e;
  std::optional<codegen::CompiledPair> pair;
  if (ir::Status e = compile_programs(d, pass, textures, pair); !e) return e;
  Geometry geo;
  if (ir::Status e = build_geometry(pass, geo); !e) return e;
  SampledImages images{};
  if (ir::Status e = bind_sampled(d, pass, textures, *pair, out, images); !e) return e;
  if (ir::Status e = upload_geometry(d, geo, out); !e) return e;
  // Descriptor set 0 and the pipeline layout.
  Bindings bound;
  if (ir::Status s = create_bindings(d, out.objects, *pair, pass, images, bound); !s)
    return draw_failure(s.message());
  out.layout = bound.layout;
  out.set = bound.set;
  out.trace = bound.trace;
  out.trace_info = pair->ps.trace;
  if (ir::Status e =
          create_render_objects(d, pass, textures, *pair, bound.layout, bound.layout_bindings, out);
      !e)
    return e;
  place_viewport(pass, *textures.target, !geo.indices.empty(), out);
  return ir::ok_status();
}

void record_draw(VkCommandBuffer cb, const Device::Impl& d, PreparedDraw& p) {
  for (uint32_t s = 0; s < pass::kSamplerSlots; ++s)
    if (Resident* r = p.sampled[s])
      p.fetched[s] ? record_as_fetched(cb, *r) : record_as_sampled(cb, d, *r);
  Resident& target = *p.target;
  record_as_target(cb, target);
  for (Resident* m : p.more_targets)
    if (m) record_as_target(cb, *m);
  if (p.stencil) record_as_stencil(cb, *p.stencil);
  VkRenderPassBeginInfo rbi{};
  rbi.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  rbi.renderPass = p.render_pass;
  rbi.framebuffer = p.framebuffer;
  rbi.renderArea = {{0, 0}, {target.width, target.height}};
  vkCmdBeginRenderPass(cb, &rbi, VK_SUBPASS_CONTENTS_INLINE);
  if (p.visible) {
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, p.pipeline);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, p.layout, 0, 1, &p.set, 0,
                            nullptr);
    VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cb, 0, 1, &p.vertices.buffer, &offset);
    vkCmdBindIndexBuffer(cb, p.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdSetViewport(cb, 0, 1, &p.viewport);
    vkCmdSetScissor(cb, 0, 1, &p.scissor);
    vkCmdDrawIndexed(cb, p.index_count, 1, 0, 0, 0);
  }
  vkCmdEndRenderPass(cb);
}

ir::Status submit_draw(Device::Impl& d, PreparedDraw& draw) {
  LayoutSnapshot snapshot;
  snapshot.save(*draw.target);
  for (Resident* r : draw.more_targets)
    if (r) snapshot.save(*r);
  if (draw.stencil) snapshot.save(*draw.stencil);
  for (Resident* r : draw.sampled)
    if (r) snapshot.save(*r);
  ir::Status err = timed_draw_submission(
      [&] { return submit_and_wait(d, [&](VkCommandBuffer cb) { record_draw(cb, d, draw); }); });
  if (!err) snapshot.restore();
  return err;
}

ir::Result<pass::DrawReport> draw_pass(Device::Impl& d, const pass::Pass& pass,
                                       const DrawTextures& textures) {
  pass::DrawReport res;
  const auto t0 = Clock::now();
  PreparedDraw prepared;
  if (ir::Status e = prepare_draw(d, pass, textures, prepared); !e) return std::move(e).failure();
  Resident& target = *textures.target;

  // The staging buffer of a host target: its contents go up, the result comes back.
  Cleanup cleanup;
  Buffer rt_staging;
  if (textures.host_target) {
    const VkDeviceSize rt_bytes =
        VkDeviceSize{target.width} * target.height * bytes_per_pixel(target.format);
    ir::Status err = create_buffer(
        d, cleanup, rt_bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
        rt_staging);
    if (!err) return std::move(err).failure();
    pack_pixels(*textures.host_target, rt_staging.mapped);
  }
  res.setup_ms = ms_since(t0);

  LayoutSnapshot snapshot;
  snapshot.save(target);
  for (Resident* r : prepared.more_targets)
    if (r) snapshot.save(*r);
  if (prepared.stencil) snapshot.save(*prepared.stencil);
  for (Resident* r : prepared.sampled)
    if (r) snapshot.save(*r);
  const auto t1 = Clock::now();
  ir::Status err = timed_draw_submission([&] {
    return submit_and_wait(d, [&](VkCommandBuffer cb) {
      if (textures.host_target) record_upload(cb, target, rt_staging.buffer);
      record_draw(cb, d, prepared);
      if (prepared.trace.buffer) { // the pixel stage's record made visible to the host
        VkMemoryBarrier mb{};
        mb.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
        mb.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                             0, 1, &mb, 0, nullptr, 0, nullptr);
      }
      if (textures.host_target) record_readback(cb, target, rt_staging.buffer);
    });
  });
  if (!err) {
    snapshot.restore();
    return std::move(err).failure();
  }
  res.draw_ms = ms_since(t1);
  if (textures.host_target) unpack_pixels(rt_staging.mapped, *textures.host_target);
  if (textures.trace_out && prepared.trace_info) read_trace(prepared, *textures.trace_out);
  return res;
}

} // namespace tierlift::vulkan
