// TextureSet: textures kept in device memory between draws (texture_set.h).
#include "tierlift/vulkan/texture_set.h"

#include <chrono>
#include <map>

#include <fmt/format.h>

#include "draw_cache.h"
#include "pass_draw.h"
#include "pipeline.h"
#include "program_reuse.h"
#include "tierlift/ir/result.h"

namespace tierlift::vulkan {

struct TextureSet::State {
  explicit State(Device::Impl& impl) : d(impl) {}
  ~State() {
    if (pending != VK_NULL_HANDLE) (void)submit_commands(d, pending);
  }

  Device::Impl& d;
  std::map<uint32_t, std::unique_ptr<Resident>> textures;
  // set_reuse_programs: kept across clear(); destroyed after the draws that use its pipelines.
  std::unique_ptr<ProgramReuse> reuse;
  DrawCache draws;                          // destroyed before the textures it refers to
  VkCommandBuffer pending = VK_NULL_HANDLE; // batched draws not yet submitted
  bool batching = false;
  uint32_t next_id = 1;

  Resident* find(TextureId id) {
    auto it = textures.find(static_cast<uint32_t>(id));
    return it == textures.end() ? nullptr : it->second.get();
  }
  ir::Status flush() { // `pending` holds batched draws only
    if (pending == VK_NULL_HANDLE) return ir::ok_status();
    return timed_draw_submission([&] { return submit_commands(d, pending); });
  }
};

namespace {

std::string unknown(TextureId id) {
  return fmt::format("no texture {} in this set", static_cast<uint32_t>(id));
}

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

TextureSet::TextureSet(Device& device)
    : device_(device), state_(std::make_unique<State>(*device.impl_)) {}
TextureSet::~TextureSet() = default;

ir::Result<TextureId> TextureSet::create(uint32_t width, uint32_t height, img::Format format) {
  if (!img::valid_size(width, height))
    return draw_failure(fmt::format("texture size {}x{}: each side must be 1..{}", width, height,
                                    img::kMaxDimension));
  std::unique_ptr<Resident> r;
  if (ir::Status err = create_resident(*device_.impl_, width, height, format, r); !err)
    return std::move(err).failure();
  const uint32_t id = state_->next_id++;
  state_->textures.emplace(id, std::move(r));
  return static_cast<TextureId>(id);
}

ir::Result<TextureId> TextureSet::create_stencil(uint32_t width, uint32_t height) {
  if (!img::valid_size(width, height))
    return draw_failure(fmt::format("stencil buffer size {}x{}: each side must be 1..{}", width,
                                    height, img::kMaxDimension));
  std::unique_ptr<Resident> r;
  if (ir::Status err = create_stencil_resident(*device_.impl_, width, height, r); !err)
    return std::move(err).failure();
  const uint32_t id = state_->next_id++;
  state_->textures.emplace(id, std::move(r));
  return static_cast<TextureId>(id);
}

ir::Result<TextureId> TextureSet::create_depth(uint32_t width, uint32_t height, float clear) {
  if (!img::valid_size(width, height))
    return draw_failure(fmt::format("depth buffer size {}x{}: each side must be 1..{}", width,
                                    height, img::kMaxDimension));
  std::unique_ptr<Resident> r;
  if (ir::Status err = create_depth_resident(*device_.impl_, width, height, clear, r); !err)
    return std::move(err).failure();
  const uint32_t id = state_->next_id++;
  state_->textures.emplace(id, std::move(r));
  return static_cast<TextureId>(id);
}

ir::Status TextureSet::upload(TextureId id, const img::Image& image) {
  Resident* r = state_->find(id);
  if (!r) return draw_failure(unknown(id));
  if (r->stencil)
    return draw_failure(fmt::format("texture {} is a stencil buffer: it starts at zero and only "
                                    "draws change it",
                                    static_cast<uint32_t>(id)));
  if (image.width != r->width || image.height != r->height ||
      image.rgba.size() != size_t{image.width} * image.height * 4)
    return draw_failure(fmt::format("upload of a {}x{} image into the {}x{} texture {}",
                                    image.width, image.height, r->width, r->height,
                                    static_cast<uint32_t>(id)));
  if (ir::Status err = state_->flush(); !err) return std::move(err).failure();
  Device::Impl& d = *device_.impl_;
  Cleanup cleanup;
  Buffer staging;
  const VkDeviceSize bytes = VkDeviceSize{r->width} * r->height * r->packed_bytes();
  if (ir::Status err = create_buffer(d, cleanup, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, staging);
      !err)
    return std::move(err).failure();
  if (r->depth) { // a depth buffer takes the image's red channel, one float per pixel
    auto* out = static_cast<float*>(staging.mapped);
    for (size_t i = 0; i < size_t{r->width} * r->height; ++i) out[i] = image.rgba[4 * i];
  } else if (image.format == r->format) {
    pack_pixels(image, staging.mapped);
  } else {
    img::Image stored = image; // pack_pixels applies the store rule of image.format
    stored.format = r->format;
    pack_pixels(stored, staging.mapped);
  }
  const TrackedImage before = r->stored;
  const bool shadow_current = r->shadow_current;
  ir::Status err =
      submit_and_wait(d, [&](VkCommandBuffer cb) { record_upload(cb, *r, staging.buffer); });
  if (!err) {
    r->stored = before;
    r->shadow_current = shadow_current;
  }
  return err;
}

ir::Result<img::Image> TextureSet::read(TextureId id) {
  Resident* r = state_->find(id);
  if (!r) return draw_failure(unknown(id));
  if (ir::Status err = state_->flush(); !err) return std::move(err).failure();
  Device::Impl& d = *device_.impl_;
  Cleanup cleanup;
  Buffer staging;
  const VkDeviceSize bytes = VkDeviceSize{r->width} * r->height * r->packed_bytes();
  if (ir::Status err = create_buffer(d, cleanup, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, staging);
      !err)
    return std::move(err).failure();
  const TrackedImage before = r->stored;
  ir::Status err =
      submit_and_wait(d, [&](VkCommandBuffer cb) { record_readback(cb, *r, staging.buffer); });
  if (!err) {
    r->stored = before;
    return std::move(err).failure();
  }
  if (r->stencil) { // as the CPU device reads its stencil buffer: the value in red
    img::Image image(r->width, r->height, img::Format::RGBA32F);
    const auto* bytes_in = static_cast<const uint8_t*>(staging.mapped);
    for (size_t i = 0; i < size_t{r->width} * r->height; ++i) image.rgba[4 * i] = bytes_in[i];
    return image;
  }
  if (r->depth) { // likewise a depth buffer: its float in red
    img::Image image(r->width, r->height, img::Format::RGBA32F);
    const auto* floats = static_cast<const float*>(staging.mapped);
    for (size_t i = 0; i < size_t{r->width} * r->height; ++i) image.rgba[4 * i] = floats[i];
    return image;
  }
  img::Image image(r->width, r->height, r->format);
  unpack_pixels(staging.mapped, image);
  return image;
}

namespace {

// The textures of a draw by id; an error names the unknown one.
ir::Status resolve(TextureSet::State& s, const StageTextures& stages, const RenderTargets& targets,
                   DrawTextures& out) {
  out.reuse = s.reuse.get();
  out.target = s.find(targets.color[0]);
  if (!out.target) return draw_failure("render target: " + unknown(targets.color[0]));
  for (uint32_t i = 1; i < targets.color.size(); ++i) {
    if (targets.color[i] == TextureId::None) continue;
    out.more_targets[i - 1] = s.find(targets.color[i]);
    if (!out.more_targets[i - 1])
      return draw_failure(fmt::format("render target {}: {}", i, unknown(targets.color[i])));
  }
  if (targets.stencil != TextureId::None) {
    out.stencil = s.find(targets.stencil);
    if (!out.stencil) return draw_failure("stencil buffer: " + unknown(targets.stencil));
  }
  if (targets.depth != TextureId::None) {
    out.depth = s.find(targets.depth);
    if (!out.depth) return draw_failure("depth buffer: " + unknown(targets.depth));
  }
  for (uint32_t k = 0; k < pass::kSamplerSlots; ++k) {
    if (stages[k] == TextureId::None) continue;
    out.stages[k] = s.find(stages[k]);
    if (!out.stages[k])
      return draw_failure(fmt::format("{}s{}: {}", k < pass::kMaxSamplers ? "" : "vertex ",
                                      k % pass::kMaxSamplers, unknown(stages[k])));
  }
  return ir::ok_status();
}

// The cached draw of `pass`, made now if there is none (a draw_failure when it cannot be
// made); nullptr when the pass is not cached.
ir::Result<PreparedDraw*> cached_draw(TextureSet::State& s, const pass::Pass& pass,
                                      const DrawTextures& t) {
  std::optional<std::string> key = draw_key(pass, t);
  if (!key) return static_cast<PreparedDraw*>(nullptr);
  if (PreparedDraw* p = s.draws.find(*key)) return p;
  auto entry = std::make_unique<CachedDraw>();
  if (ir::Status e = prepare_draw(s.d, pass, t, entry->draw); !e) return std::move(e).failure();
  return &s.draws.insert(*key, pass, std::move(entry));
}

} // namespace

ir::Status TextureSet::prepare(const pass::Pass& pass, const StageTextures& stages,
                               TextureId target) {
  RenderTargets targets;
  targets.color[0] = target;
  return prepare(pass, stages, targets);
}

ir::Status TextureSet::prepare(const pass::Pass& pass, const StageTextures& stages,
                               const RenderTargets& targets) {
  DrawTextures textures;
  if (ir::Status e = resolve(*state_, stages, targets, textures); !e) return std::move(e).failure();
  ir::Result<PreparedDraw*> cached = cached_draw(*state_, pass, textures);
  if (!cached) return std::move(cached).failure();
  return ir::ok_status();
}

ir::Result<pass::DrawReport> TextureSet::draw(const pass::Pass& pass, const StageTextures& stages,
                                              TextureId target) {
  RenderTargets targets;
  targets.color[0] = target;
  return draw(pass, stages, targets);
}

ir::Result<pass::DrawReport> TextureSet::draw(const pass::Pass& pass, const StageTextures& stages,
                                              const RenderTargets& targets) {
  DrawTextures textures;
  if (ir::Status e = resolve(*state_, stages, targets, textures); !e) return std::move(e).failure();
  const auto t0 = std::chrono::steady_clock::now();
  ir::Result<PreparedDraw*> cached = cached_draw(*state_, pass, textures);
  if (!cached) return std::move(cached).failure();
  PreparedDraw* p = *cached;
  if (!p) { // not cached: made, drawn and destroyed now
    if (ir::Status e = state_->flush(); !e) return std::move(e).failure();
    return draw_pass(*device_.impl_, pass, textures);
  }
  pass::DrawReport res;
  res.setup_ms = ms_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  Device::Impl& d = *device_.impl_;
  if (state_->batching) {
    if (state_->pending == VK_NULL_HANDLE)
      if (ir::Status e = begin_commands(d, state_->pending); !e) return std::move(e).failure();
    record_draw(state_->pending, d, *p);
  } else {
    if (ir::Status e = submit_draw(d, *p); !e) return std::move(e).failure();
  }
  res.draw_ms = ms_since(t1);
  return res;
}

ir::Result<ShaderTrace> TextureSet::draw_traced(const pass::Pass& pass, const StageTextures& stages,
                                                TextureId target, uint32_t x, uint32_t y) {
  RenderTargets targets;
  targets.color[0] = target;
  DrawTextures textures;
  if (ir::Status e = resolve(*state_, stages, targets, textures); !e) return std::move(e).failure();
  if (ir::Status e = state_->flush(); !e) return std::move(e).failure();
  const codegen::TracePixel pixel{x, y, codegen::kTraceBinding};
  ShaderTrace out;
  textures.trace = &pixel;
  textures.trace_out = &out;
  ir::Result<pass::DrawReport> drawn = draw_pass(*device_.impl_, pass, textures);
  if (!drawn) return std::move(drawn).failure();
  return out;
}

ir::Status TextureSet::set_batching(bool on) {
  ir::Status err = state_->flush();
  state_->batching = on;
  return err;
}

void TextureSet::set_reuse_programs(bool on) {
  if (on == (state_->reuse != nullptr)) return;
  (void)state_->flush();
  state_->draws.clear(); // made the other way
  state_->reuse = on ? std::make_unique<ProgramReuse>() : nullptr;
}

size_t TextureSet::reused_pipelines() const {
  return state_->reuse ? state_->reuse->pipeline_count() : 0;
}

ir::Status TextureSet::flush() {
  return state_->flush();
}

void TextureSet::destroy(TextureId id) {
  (void)state_->flush();
  Resident* r = state_->find(id);
  if (!r) return;
  state_->draws.forget(r);
  state_->textures.erase(static_cast<uint32_t>(id));
}
void TextureSet::clear() {
  (void)state_->flush();
  state_->draws.clear();
  state_->textures.clear();
}
size_t TextureSet::size() const {
  return state_->textures.size();
}

} // namespace tierlift::vulkan
