// Scenes that do not come from JSON text (the default, --image), the scene image, and the
// warnings a set of glow parameters deserves.
#include <glm/gtc/constants.hpp>

#include "tierlift/effects/scenes/scene.h"

#include <cctype>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "scene_parts.h"
#include "tierlift/effects/scenes/default_scene.h"
#include "tierlift/io/bounded_read.h"

namespace tierlift::effects {
namespace {

// "PATH: what" (img's messages) → "PATH: error: what".
std::string file_error(const std::string& path, const std::string& message) {
  const std::string head = path + ": ";
  // A positioned image error ("PATH:LINE:COL: why", the quoted line, the caret): "error:"
  // goes after the position.
  if (message.size() > path.size() + 1 && message.starts_with(path + ":") &&
      std::isdigit(static_cast<unsigned char>(message[path.size() + 1]))) {
    const size_t colon = message.find(": ", path.size() + 1);
    if (colon != std::string::npos)
      return message.substr(0, colon) + ": error: " + message.substr(colon + 2) + "\n";
  }
  const std::string what = message.starts_with(head) ? message.substr(head.size()) : message;
  return fmt::format("{}: error: {}\n", path, what);
}

} // namespace

std::vector<std::string> glow_warnings(const EffectParams& params) {
  std::vector<std::string> out;
  const double sum = profile_weight_sum(params.profile);
  // One axis scales the glow by the sum, the second axis by the sum again.
  if (std::isfinite(sum) && sum > 0 && std::abs(sum - 1) > 1e-9) {
    const double both = sum * sum;
    out.push_back(fmt::format("profile weights sum to {:.6g}: the glow is {:.3g} % {} than its "
                              "sources ({:.4g} after both axes)",
                              sum, std::abs(both - 1) * 100, both < 1 ? "darker" : "brighter",
                              both));
  }
  // Tier dx7 carries the weights as 8-bit colours: what that costs against the kernel.
  if (params.tier == Tier::Dx7) {
    const ir::Result<std::vector<BlurTap>> taps =
        sample_blur_profile(params.profile, params.downsample);
    std::vector<double> weights;
    if (taps)
      for (const BlurTap& t : *taps) weights.push_back(t.weight);
    if (taps && !taps->empty())
      out.push_back(quantization_summary(weights, params.weight_rounding));
  }
  // The stress regimes (docs/stress.md) a scene's parameters alone reveal.
  if (params.format == img::Format::RGBA8) {
    // Each ONE/ONE blur pass stores its running sum in 8 bits, moving it by up to half a step:
    // P passes an axis drift by up to P/255 (sigma.limit.rgba8: a glow of 0.25 comes out 0).
    const ir::Result<std::vector<BlurTap>> sampled =
        sample_blur_profile(params.profile, params.downsample);
    const size_t taps = sampled ? sampled->size() : 0;
    const unsigned per = params.tier == Tier::Dx8    ? kTapsPerBlurPassDx8
                         : params.tier == Tier::Dx7  ? kTapsPerBlurPassDx7
                         : params.tier == Tier::Dx9c ? kTapsPerBlurPassDx9c
                                                     : kTapsPerBlurPassDx9;
    const size_t passes = (taps + per - 1) / per;
    if (passes > 4)
      out.push_back(fmt::format("rgba8 with {} blur passes per axis: each ONE/ONE pass rounds "
                                "its sum to 1/255, a drift of up to {:.3g} from the ideal glow; "
                                "use rgba16f, fewer taps (taps) or a larger downsample",
                                passes, double(passes) / 255));
    // A glow of 1/intensity already saturates the frame to 1 (intensity.1000.rgba8).
    if (params.intensity > 4)
      out.push_back(fmt::format("intensity {:g} in rgba8: any glow above {:.3g} saturates the "
                                "frame to 1 and the halo's shape is lost; use rgba16f or "
                                "rgba32f, or a lower intensity",
                                params.intensity, 1 / params.intensity));
  }
  return out;
}

std::vector<std::string> image_warnings(const img::Image& image) {
  bool all_one = true, all_zero = true;
  for (size_t i = 3; i < image.rgba.size(); i += 4) {
    all_one = all_one && image.rgba[i] >= 1.0f;
    all_zero = all_zero && image.rgba[i] <= 0.0f;
  }
  if (image.rgba.empty()) return {};
  if (all_one) return {"the image's alpha is 1 everywhere: all of it glows (no alpha channel?)"};
  if (all_zero) return {"the image's alpha is 0 everywhere: nothing glows"};
  return {};
}

ir::Result<Scene> load_scene_file(const std::string& path) {
  const std::string name = path == "-" ? "<stdin>" : path;
  // Within the scene cap: a device or a pipe given as the scene is refused after 1 MiB.
  ir::Result<std::string> text = io::read_bounded(path, io::kSceneCap);
  if (!text)
    return ir::fail_rendered(name, std::string(kSceneIoRule), file_error(name, text.message()));
  const std::string base_dir =
      path == "-" ? std::string() : std::filesystem::path(path).parent_path().string();
  return parse_scene(*text, name, base_dir);
}

Scene default_scene() {
  Scene s;
  s.image = std::string(kBuiltinNeon);
  s.params.width = kDefaultSceneWidth;
  s.params.height = kDefaultSceneHeight;
  s.warnings = glow_warnings(s.params);
  return s;
}

ir::Result<Scene> scene_from_png(const std::string& png_path) {
  img::ImageResult png = img::read_image(png_path); // PNG, or PFM for HDR values
  if (!png)
    return ir::fail_rendered(png_path,
                             std::string(img::is_io_error(png) ? kSceneIoRule : kSceneRule),
                             file_error(png_path, png.message()));
  Scene s;
  s.image = png_path;
  s.params.width = png->width;
  s.params.height = png->height;
  s.warnings = glow_warnings(s.params);
  for (std::string& w : image_warnings(*png)) s.warnings.push_back(std::move(w));
  return s;
}

ir::Result<Scene> load_scene(const std::string& scene_path, const std::string& png_path) {
  if (!scene_path.empty()) return load_scene_file(scene_path);
  if (!png_path.empty()) return scene_from_png(png_path);
  return default_scene();
}

img::ImageResult load_scene_image(const Scene& scene) {
  return load_scene_image(scene, 1);
}

img::ImageResult load_scene_image(const Scene& scene, unsigned frame) {
  auto fail = [&](std::string message) -> img::ImageResult {
    return ir::fail(scene.image, "scene", std::move(message));
  };
  const EffectParams& p = scene.params;
  if (!img::valid_size(p.width, p.height))
    return fail(fmt::format("{}: the scene size {}x{} is outside 1..{}", scene.image, p.width,
                            p.height, img::kMaxDimension));
  if (scene.image == kBuiltinNeon) {
    const Motion& m = p.motion;
    const double angle =
        m.on() ? glm::two_pi<double>() * double((frame - 1) % m.period) / m.period : 0;
    return img::ImageResult(make_default_scene(p.width, p.height, img::Format::RGBA32F,
                                               m.on() ? m.radius * p.height : 0, angle));
  }
  if (scene.image.starts_with("builtin:"))
    return fail(
        fmt::format("{}: not a built-in image (the built-in is {})", scene.image, kBuiltinNeon));
  img::ImageResult png = img::read_image(scene.image);
  if (!png) return png;
  if (png->width != p.width || png->height != p.height)
    return fail(fmt::format("{}: the image is {}x{} but the scene is {}x{} (did the file change?)",
                            scene.image, png->width, png->height, p.width, p.height));
  png->format = img::Format::RGBA32F; // 8-bit values k/255 are exact floats already; PFM is
  return png;
}

} // namespace tierlift::effects
