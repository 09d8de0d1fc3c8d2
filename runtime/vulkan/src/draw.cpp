// Device::draw: one cpu::Pass on Vulkan — programs, vertex data, constants, textures,
// descriptors, pipeline, the draw and the readback (see device.h for the mapping).
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

} // namespace

DrawResult Device::draw(const cpu::Pass& pass, img::Image& target, const DrawOptions& options) {
  DrawResult res;
  auto fail = [&](std::string msg) {
    res.ok = false;
    res.error = std::move(msg);
    return res;
  };
  const auto t0 = Clock::now();
  Impl& d = *impl_;
  if (target.width == 0 || target.height == 0 || target.width > img::kMaxDimension ||
      target.height > img::kMaxDimension)
    return fail("render target size must be 1..16384 on each side");
  if (target.rgba.size() != size_t{target.width} * target.height * 4)
    return fail("render target pixel buffer does not match its size");
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
  err = create_bindings(d, cleanup, *pair, pass, bound);
  if (!err.empty()) return fail(err);
  const std::vector<Texture>& textures = bound.textures;
  const VkPipelineLayout layout = bound.layout;
  const VkDescriptorSet set = bound.set;

  // Render target, its staging buffer (upload, then readback), render pass, pipeline.
  const VkFormat rt_format = vk_format(target.format);
  VkFormatProperties rt_props;
  vkGetPhysicalDeviceFormatProperties(d.physical, rt_format, &rt_props);
  if (!(rt_props.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT) ||
      (pass.blend != cpu::BlendMode::Replace &&
       !(rt_props.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT)))
    return fail(fmt::format("the Vulkan device cannot render (and blend) to {}",
                            img::format_name(target.format)));
  Image2D rt;
  Buffer rt_staging;
  err = create_image(d, cleanup, target.width, target.height, rt_format,
                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                         VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                     rt);
  const VkDeviceSize rt_bytes =
      VkDeviceSize{target.width} * target.height * bytes_per_pixel(target.format);
  if (err.empty())
    err = create_buffer(d, cleanup, rt_bytes,
                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        rt_staging);
  if (!err.empty()) return fail(err);
  pack_pixels(target, rt_staging.mapped);
  VkRenderPass rp = VK_NULL_HANDLE;
  VkFramebuffer fb = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  err = create_render_pass(d, cleanup, rt_format, rp);
  if (err.empty()) err = create_framebuffer(d, cleanup, rp, rt, fb);
  PipelineDesc pd;
  pd.vs = &pair->vs;
  pd.ps = &pair->ps;
  pd.ps_words = options.flat_varyings ? decorate_inputs_flat(pair->ps.words) : pair->ps.words;
  pd.blend = pass.blend;
  pd.render_pass = rp;
  pd.layout = layout;
  pd.vertex_stride = kVertexStride;
  if (err.empty()) err = create_pipeline(d, cleanup, pd, pipeline);
  if (!err.empty()) return fail(err);

  // Uploads: target contents and textures.
  err = submit_and_wait(d, [&](VkCommandBuffer cb) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    image_barrier(cb, rt.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                  VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT);
    copy.imageExtent = {target.width, target.height, 1};
    vkCmdCopyBufferToImage(cb, rt_staging.buffer, rt.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &copy);
    image_barrier(cb, rt.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
    for (const Texture& t : textures) {
      image_barrier(cb, t.image.image, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
      copy.imageExtent = {t.image.width, t.image.height, 1};
      vkCmdCopyBufferToImage(cb, t.staging.buffer, t.image.image,
                             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
      image_barrier(cb, t.image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
    }
  });
  if (!err.empty()) return fail(err);

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
    VkRenderPassBeginInfo rbi{};
    rbi.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    rbi.renderPass = rp;
    rbi.framebuffer = fb;
    rbi.renderArea = {{0, 0}, {target.width, target.height}};
    vkCmdBeginRenderPass(cb, &rbi, VK_SUBPASS_CONTENTS_INLINE);
    if (visible) {
      vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, nullptr);
      VkDeviceSize offset = 0;
      vkCmdBindVertexBuffers(cb, 0, 1, &vbuf.buffer, &offset);
      vkCmdBindIndexBuffer(cb, ibuf.buffer, 0, VK_INDEX_TYPE_UINT32);
      vkCmdSetViewport(cb, 0, 1, &viewport);
      vkCmdSetScissor(cb, 0, 1, &scissor);
      vkCmdDrawIndexed(cb, static_cast<uint32_t>(geo.indices.size()), 1, 0, 0, 0);
    }
    vkCmdEndRenderPass(cb);
    image_barrier(cb, rt.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {target.width, target.height, 1};
    vkCmdCopyImageToBuffer(cb, rt.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, rt_staging.buffer, 1,
                           &copy);
    VkBufferMemoryBarrier bb{};
    bb.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    bb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    bb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    bb.buffer = rt_staging.buffer;
    bb.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0,
                         nullptr, 1, &bb, 0, nullptr);
  });
  if (!err.empty()) return fail(err);
  res.draw_ms = ms_since(t1);
  unpack_pixels(rt_staging.mapped, target);
  res.ok = true;
  return res;
}

} // namespace tierlift::vulkan
