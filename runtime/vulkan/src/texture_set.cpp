// TextureSet: textures kept in device memory between draws (texture_set.h).
#include "tierlift/vulkan/texture_set.h"

#include <map>

#include <fmt/format.h>

#include "pass_draw.h"

namespace tierlift::vulkan {

struct TextureSet::State {
  std::map<uint32_t, std::unique_ptr<Resident>> textures;
  uint32_t next_id = 1;

  Resident* find(TextureId id) {
    auto it = textures.find(static_cast<uint32_t>(id));
    return it == textures.end() ? nullptr : it->second.get();
  }
};

namespace {

std::string unknown(TextureId id) {
  return fmt::format("no texture {} in this set", static_cast<uint32_t>(id));
}

} // namespace

TextureSet::TextureSet(Device& device) : device_(device), state_(std::make_unique<State>()) {}
TextureSet::~TextureSet() = default;

std::string TextureSet::create(uint32_t width, uint32_t height, img::Format format,
                               TextureId& out) {
  if (width == 0 || height == 0 || width > img::kMaxDimension || height > img::kMaxDimension)
    return fmt::format("texture size {}x{}: each side must be 1..{}", width, height,
                       img::kMaxDimension);
  std::unique_ptr<Resident> r;
  if (std::string err = create_resident(*device_.impl_, width, height, format, r); !err.empty())
    return err;
  const uint32_t id = state_->next_id++;
  state_->textures.emplace(id, std::move(r));
  out = static_cast<TextureId>(id);
  return {};
}

std::string TextureSet::upload(TextureId id, const img::Image& image) {
  Resident* r = state_->find(id);
  if (!r) return unknown(id);
  if (image.width != r->width || image.height != r->height ||
      image.rgba.size() != size_t{image.width} * image.height * 4)
    return fmt::format("upload of a {}x{} image into the {}x{} texture {}", image.width,
                       image.height, r->width, r->height, static_cast<uint32_t>(id));
  Device::Impl& d = *device_.impl_;
  Cleanup cleanup;
  Buffer staging;
  const VkDeviceSize bytes = VkDeviceSize{r->width} * r->height * bytes_per_pixel(r->format);
  if (std::string err = create_buffer(d, cleanup, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, staging);
      !err.empty())
    return err;
  if (image.format == r->format) {
    pack_pixels(image, staging.mapped);
  } else {
    img::Image stored = image; // pack_pixels applies the store rule of image.format
    stored.format = r->format;
    pack_pixels(stored, staging.mapped);
  }
  const TrackedImage before = r->stored;
  const bool shadow_current = r->shadow_current;
  std::string err =
      submit_and_wait(d, [&](VkCommandBuffer cb) { record_upload(cb, *r, staging.buffer); });
  if (!err.empty()) {
    r->stored = before;
    r->shadow_current = shadow_current;
  }
  return err;
}

std::string TextureSet::read(TextureId id, img::Image& out) {
  Resident* r = state_->find(id);
  if (!r) return unknown(id);
  Device::Impl& d = *device_.impl_;
  Cleanup cleanup;
  Buffer staging;
  const VkDeviceSize bytes = VkDeviceSize{r->width} * r->height * bytes_per_pixel(r->format);
  if (std::string err = create_buffer(d, cleanup, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, staging);
      !err.empty())
    return err;
  const TrackedImage before = r->stored;
  std::string err =
      submit_and_wait(d, [&](VkCommandBuffer cb) { record_readback(cb, *r, staging.buffer); });
  if (!err.empty()) {
    r->stored = before;
    return err;
  }
  img::Image image(r->width, r->height, r->format);
  unpack_pixels(staging.mapped, image);
  out = std::move(image);
  return {};
}

DrawResult TextureSet::draw(const cpu::Pass& pass, const StageTextures& stages, TextureId target,
                            const DrawOptions& options) {
  DrawTextures textures;
  textures.target = state_->find(target);
  DrawResult res;
  if (!textures.target) {
    res.error = "render target: " + unknown(target);
    return res;
  }
  for (uint32_t s = 0; s < cpu::kMaxSamplers; ++s) {
    if (stages[s] == TextureId::None) continue;
    textures.stages[s] = state_->find(stages[s]);
    if (!textures.stages[s]) {
      res.error = fmt::format("s{}: {}", s, unknown(stages[s]));
      return res;
    }
  }
  return draw_pass(*device_.impl_, pass, textures, options);
}

void TextureSet::destroy(TextureId id) {
  state_->textures.erase(static_cast<uint32_t>(id));
}
void TextureSet::clear() {
  state_->textures.clear();
}
size_t TextureSet::size() const {
  return state_->textures.size();
}

} // namespace tierlift::vulkan
