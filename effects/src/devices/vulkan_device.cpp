// The Vulkan device behind the PassDevice interface: the
// graph's textures live in a vulkan::TextureSet for the run, so passes read and write device
// memory and nothing comes back to the host until read_texture asks for it. A stencil
// texture (TextureDesc::stencil) is a stencil buffer there, a depth texture (TextureDesc::depth)
// a D32_SFLOAT depth buffer; read_texture returns either as the CPU device does (RGBA32F, the
// value in red), so the agreement table compares them too.
//
// begin_run makes every pass's draw ahead (SPIR-V, pipeline, descriptor set, framebuffer:
// the set keeps them), so a pass costs its commands only; passes are recorded into one
// command buffer, with barriers between them, that finish() or a read submits: one submit
// per frame instead of a submit and a wait per pass.
#include "tierlift/effects/graph/device.h"

#include <fmt/format.h>

#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/effects/graph/vulkan_device.h"
#include "tierlift/vulkan/device.h"
#include "tierlift/vulkan/process_device.h"
#include "tierlift/vulkan/texture_set.h"

namespace tierlift::effects {
namespace {

class VulkanPassDevice final : public PassDevice {
public:
  VulkanPassDevice(vulkan::Device& device, bool reuse_programs)
      : device_(device), textures_(device) {
    textures_.set_reuse_programs(reuse_programs);
  }
  std::string name() const override { return "vulkan"; }

  ir::Status begin_run(const EffectGraph& graph, const ImageMap& inputs) override {
    graph_ = nullptr;
    ids_.clear();
    textures_.clear();
    for (const TextureDesc& t : graph.textures) {
      ir::Result<vulkan::TextureId> id =
          t.stencil ? textures_.create_stencil(t.width, t.height)
          : t.depth ? textures_.create_depth(t.width, t.height, t.depth_clear)
                    : textures_.create(t.width, t.height, t.format);
      ir::Status uploaded = ir::ok_status();
      if (auto it = inputs.find(t.name); id && it != inputs.end())
        uploaded = textures_.upload(*id, it->second);
      else if (id && t.depth && t.contents) // a depth buffer's starting values (--depth-in)
        uploaded = textures_.upload(*id, *t.contents);
      if (!id || !uploaded) {
        drop();
        return device_error(
            fmt::format("texture '{}': {}", t.name, id ? uploaded.message() : id.message()));
      }
      ids_[t.name] = *id;
    }
    graph_ = &graph;
    for (const PassDesc& desc : graph.passes) {
      Draw draw;
      std::string e = make_draw(desc, draw);
      if (e.empty())
        if (ir::Status made = textures_.prepare(draw.pass, draw.stages, draw.targets); !made)
          e = made.message();
      if (!e.empty()) {
        drop();
        return device_error(fmt::format("pass '{}': {}", desc.name, e));
      }
    }
    device_.save_pipeline_cache(); // for the next run (a no-op when nothing was added)
    return textures_.set_batching(true);
  }

  ir::Result<pass::DrawReport> draw(const PassDesc& desc) override {
    if (!graph_) return device_error("no run was begun");
    Draw made;
    if (std::string e = make_draw(desc, made); !e.empty()) return device_error(std::move(e));
    // No pixel counters on the GPU: the report holds the times only.
    return textures_.draw(made.pass, made.stages, made.targets);
  }

  ir::Status finish() override { return textures_.flush(); }

  // TextureSet::upload flushes the passes recorded so far first, so the passes before it
  // read the old image and those after it the new one.
  ir::Status update_input(const std::string& name, const img::Image& image) override {
    auto it = ids_.find(name);
    if (!graph_ || it == ids_.end()) return device_error(fmt::format("no input '{}'", name));
    return textures_.upload(it->second, image);
  }

  ir::Result<img::Image> read_texture(const std::string& name) override {
    auto it = ids_.find(name);
    if (it == ids_.end()) return device_error(fmt::format("no texture '{}'", name));
    return textures_.read(it->second);
  }

private:
  struct Draw {
    pass::Pass pass;
    vulkan::StageTextures stages{};
    vulkan::RenderTargets targets; // oC0..oC3 and the stencil buffer
  };

  std::string make_draw(const PassDesc& desc, Draw& out) const {
    auto target = ids_.find(desc.target);
    if (target == ids_.end()) return fmt::format("no texture '{}'", desc.target);
    if (desc.more_targets.size() + 1 > out.targets.color.size())
      return fmt::format("pass '{}': more than {} render targets", desc.name,
                         out.targets.color.size());
    for (size_t i = 0; i < desc.more_targets.size(); ++i) {
      auto more = ids_.find(desc.more_targets[i]);
      if (more == ids_.end()) return fmt::format("no texture '{}'", desc.more_targets[i]);
      out.targets.color[i + 1] = more->second;
    }
    if (!desc.stencil.empty()) {
      auto s = ids_.find(desc.stencil);
      if (s == ids_.end()) return fmt::format("no stencil texture '{}'", desc.stencil);
      out.targets.stencil = s->second;
    }
    if (!desc.depth.empty()) {
      auto z = ids_.find(desc.depth);
      if (z == ids_.end()) return fmt::format("no depth texture '{}'", desc.depth);
      out.targets.depth = z->second;
    }
    for (const TextureBind& b : desc.textures) {
      auto it = ids_.find(b.texture);
      const uint32_t slot = pass::sampler_slot(b.stage); // the vertex stage's sN after s0..s15
      if (it == ids_.end() || slot >= out.stages.size())
        return fmt::format("pass '{}': texture '{}' has no image", desc.name, b.texture);
      out.stages[slot] = it->second;
    }
    out.pass = graph_draw(desc, graph_->conventions);
    out.targets.color[0] = target->second;
    return {};
  }

  void drop() {
    graph_ = nullptr;
    textures_.clear();
    ids_.clear();
  }

  vulkan::Device& device_;
  vulkan::TextureSet textures_;
  const EffectGraph* graph_ = nullptr;
  std::map<std::string, vulkan::TextureId, std::less<>> ids_;
};

} // namespace

std::unique_ptr<PassDevice> make_vulkan_pass_device(vulkan::Device& device) {
  return std::make_unique<VulkanPassDevice>(device, false);
}

std::unique_ptr<PassDevice> make_vulkan_pass_device(vulkan::Device& device,
                                                    const VulkanPassOptions& options) {
  return std::make_unique<VulkanPassDevice>(device, options.reuse_programs);
}

ir::Result<vulkan::Device*> vulkan_device(const std::string& gpu) {
  vulkan::DeviceOptions options;
  options.gpu_filter = gpu;
  return vulkan::process_device(options);
}

std::string vulkan_device_name(const vulkan::Device& device) {
  return device.name();
}

} // namespace tierlift::effects
