// What runs an effect graph's passes: the CPU device (the interpreter, cpu::draw), the
// Vulkan device (SPIR-V on lavapipe) and the analytic device (the same graph as math, in
// double; analytic_device.h). A device owns the graph's textures for the length of a run:
// inputs are handed over once (begin_run), every pass renders into a texture the device
// keeps (on Vulkan: device memory, no readback between passes), and images come back only
// when asked for (read_texture: the agreement table, the files, the end of the run).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "tierlift/cpu/draw.h"
#include "tierlift/effects/graph/graph.h"
#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"

namespace tierlift::vulkan {
class Device;
}

namespace tierlift::effects {

using ImageMap = std::map<std::string, img::Image, std::less<>>;

class PassDevice {
public:
  virtual ~PassDevice() = default;
  virtual std::string name() const = 0; // "cpu", "vulkan", "analytic"
  // Starts a run of `graph` (already checked by check_graph): every texture is created at
  // its declared size and format; inputs take their image from `inputs` (already at the
  // declared size and stored in the declared format); every other texture starts at zero.
  // A device runs one graph at a time; begin_run drops what an earlier run left.
  // Every failure below carries an error whose message says why: rule "device" (the
  // device's name as its subject) for the device's own checks, or the failure of the
  // library below passed on (vulkan::TextureSet's, cpu::draw's); run_graph adds the pass and
  // the device to the message.
  virtual ir::Status begin_run(const EffectGraph& graph, const ImageMap& inputs) = 0;
  // Draws one pass of that graph (named `draw`, not "run": an IR pass is a transform, a
  // graph's pass is a draw): it samples the textures it binds and renders into its
  // target with its blend mode; the target's format is the store rule. The report holds what
  // the device counts (the CPU device: pixels shaded and killed; the others leave them 0); a
  // success may carry warnings (the CPU device: "nothing-drawn" when no triangle reached
  // the screen).
  virtual ir::Result<pass::DrawReport> draw(const PassDesc& pass) = 0;
  // Waits until every pass run so far is done (a device may queue passes: Vulkan records a
  // frame's passes into one command buffer).
  virtual ir::Status finish() { return ir::ok_status(); }
  // Replaces an input texture's contents between frames (a moving scene): `image` is at the
  // declared size and already stored in the declared format. A device that cannot refuses
  // (never ignores it).
  virtual ir::Status update_input(const std::string& name, const img::Image& /*image*/) {
    return device_error("device " + this->name() + " cannot replace input '" + name +
                        "' between frames");
  }
  // A texture's current contents (in its declared format).
  virtual ir::Result<img::Image> read_texture(const std::string& name) = 0;
  // RGBA8 textures only, and only a device that knows its exact values (the analytic one):
  // one entry per pixel, 1 where a store of it was a proven rounding tie (analytic::
  // LinearPassInput::slack: the fp32 value x·255 exactly half-way between two steps, where
  // D3D9 and Vulkan allow either), else 0. compare_runs counts a difference of one step
  // there as agreement. False: no mask (every pixel determined).
  virtual bool rounding_midpoints(const std::string& /*texture*/,
                                  std::vector<uint8_t>& /*mask*/) const {
    return false;
  }

protected:
  // The failure every method above reports: one error about this device.
  ir::Failure device_error(std::string message) const {
    return ir::fail(name(), "device", std::move(message));
  }
};

class CpuPassDevice final : public PassDevice {
public:
  // `executor`: cpu::Executor::Scalar forces the per-pixel VM (benchmarks' "before").
  explicit CpuPassDevice(unsigned threads = 0, cpu::Executor executor = cpu::Executor::Auto)
      : threads_(threads), executor_(executor) {}
  std::string name() const override { return "cpu"; }
  ir::Status begin_run(const EffectGraph& graph, const ImageMap& inputs) override;
  ir::Result<pass::DrawReport> draw(const PassDesc& pass) override;
  ir::Status update_input(const std::string& name, const img::Image& image) override;
  ir::Result<img::Image> read_texture(const std::string& name) override;

private:
  unsigned threads_;
  cpu::Executor executor_;
  const EffectGraph* graph_ = nullptr;
  ImageMap images_;
  std::map<std::string, std::vector<uint8_t>, std::less<>> stencils_; // TextureDesc::stencil
  std::map<std::string, std::vector<float>, std::less<>> depths_;     // TextureDesc::depth
  // Textures whose reused buffers still hold the run before's pixels where this run means
  // zeros: zeroed on first read, or by the draw of a pass that does not overwrite them all
  // (cpu::DrawTargets::stale) — a full-screen pass spares a clear of its target.
  std::set<std::string, std::less<>> stale_;
  void settle(const std::string& name); // zeroes `name` if it is stale
};

// Wraps a device the caller owns (and keeps alive). tierlift_vulkan is always built.
std::unique_ptr<PassDevice> make_vulkan_pass_device(vulkan::Device& device);

struct VulkanPassOptions {
  // vulkan::TextureSet::set_reuse_programs for every run of the device: one compile and one
  // pipeline per program, whatever constants the runs bind (the images do not change). For a
  // caller that draws one program on many sets of constants; the glow leaves it off (its
  // modules are specialised for the constants each pass binds).
  bool reuse_programs = false;
};
std::unique_ptr<PassDevice> make_vulkan_pass_device(vulkan::Device& device,
                                                    const VulkanPassOptions& options);

} // namespace tierlift::effects
