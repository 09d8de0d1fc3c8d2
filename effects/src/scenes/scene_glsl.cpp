// The "glsl" object of a scene ("effect": "glsl-blur"): the GLSL files of the two passes,
// their ps_2_0 twins and the kernel the analytic model checks them against. Paths are
// relative to the scene's folder; the files themselves are read when the graph is built, so
// a GLSL error names the GLSL file and line (glsl.h).
#include <cmath>

#include <fmt/format.h>

#include "scene_parts.h"
#include "tierlift/effects/glow/blur_profile.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

constexpr std::string_view kGlslKeys[] = {"horizontal",    "vertical", "horizontal_twin",
                                          "vertical_twin", "weights",  "step"};
constexpr size_t kMaxKernelTaps = kMaxBlurTaps; // as glow.taps

} // namespace

std::span<const std::string_view> scene_glsl_keys() {
  return kGlslKeys;
}

void read_glsl(const Json& j, FieldChecker& c, const std::string& base_dir,
               GlslBlurParams& params) {
  if (!c.object(j, "/glsl", kGlslKeys)) return;
  auto path = [&](const char* key, std::string& out) {
    auto it = j.find(key);
    if (it == j.end()) return;
    const std::string pointer = fmt::format("/glsl/{}", key);
    std::optional<std::string> v = c.string(*it, pointer);
    if (!v) return;
    if (v->empty()) {
      c.error(pointer, "is empty; expected a file (or leave the key out for the built-in)");
      return;
    }
    out = resolve_path(base_dir, *v);
  };
  path("horizontal", params.horizontal);
  path("vertical", params.vertical);
  path("horizontal_twin", params.horizontal_twin);
  path("vertical_twin", params.vertical_twin);
  if (auto it = j.find("weights"); it != j.end()) {
    if (!it->is_array() || it->empty() || it->size() % 2 == 0 || it->size() > kMaxKernelTaps) {
      c.error("/glsl/weights", fmt::format("{} is not an odd count (1..{}) of weights, taps −n … n",
                                           FieldChecker::shown(*it), kMaxKernelTaps));
    } else {
      std::vector<double> w;
      for (size_t i = 0; i < it->size(); ++i)
        if (auto v = c.number((*it)[i], fmt::format("/glsl/weights/{}", i), {-1000, 1000}))
          w.push_back(*v);
      if (w.size() == it->size()) params.weights = std::move(w);
    }
  }
  if (auto it = j.find("step"); it != j.end())
    if (auto v = c.number(*it, "/glsl/step", {0, 1, true})) params.step = *v;
}

} // namespace tierlift::effects
