// The seed's GLSL blur as a graph (glsl_blur.h): GLSL compiled by glslang for Vulkan, the
// ps_2_0 twin for the interpreter, the kernel for the analytic model.
#include "tierlift/effects/glow/glsl_blur.h"

#include <cmath>

#include <fmt/format.h>

#include "tierlift/glsl/glsl.h"
#include "tierlift/listings/embedded.h"

namespace tierlift::effects {
namespace {

constexpr std::string_view kQuadVs = "glow/quad4_coords.vsh";
constexpr std::string_view kBlurHTarget = "blur_h";

// The GLSL of a pass: the file when one is named, else the built-in text.
glsl::CompileResult load_glsl(const std::string& file, std::string_view builtin) {
  if (!file.empty()) return glsl::compile_fragment_file(file);
  std::optional<std::string_view> text = listings::find_embedded(builtin);
  if (!text)
    return ir::fail_rendered(std::string(builtin), std::string(glsl::kGlslRule),
                             fmt::format("no built-in GLSL '{}'\n", builtin));
  return glsl::compile_fragment(*text, "listings/" + std::string(builtin));
}

struct Axis {
  std::string name, source, target;
  std::string glsl_file, twin_file;
  std::string_view glsl_builtin, twin_builtin;
  bool vertical = false;
};

} // namespace

PlanResult build_glsl_blur(const EffectParams& params, const GlslBlurParams& g) {
  EffectPlan plan;
  const uint32_t w = params.width, h = params.height;
  if (!img::valid_size(w, h))
    return plan_failure(
        fmt::format("scene size {}x{}: expected 1..{} each", w, h, img::kMaxDimension));
  if (g.weights.empty() || g.weights.size() % 2 == 0)
    return plan_failure(
        fmt::format("glsl weights: {} given; a centred kernel has an odd count", g.weights.size()));
  if (!std::isfinite(g.step)) return plan_failure("glsl step: not a finite number");
  ListingResult vs = builtin_listing(kQuadVs, params.listing_options);
  if (!vs) return plan_failure(vs.message());
  EffectGraph& graph = plan.graph;
  graph.conventions.subtexel_bits = params.subtexel_bits;
  for (std::string_view t : {kSceneTexture, kBlurHTarget, kFinalTexture})
    graph.textures.push_back({std::string(t), w, h, params.format, t == kSceneTexture});

  const Axis axes[2] = {
      {"blur_h", std::string(kSceneTexture), std::string(kBlurHTarget), g.horizontal,
       g.horizontal_twin, kGlslBlurH, kGlslTwinH, false},
      {"blur_v", std::string(kBlurHTarget), std::string(kFinalTexture), g.vertical, g.vertical_twin,
       kGlslBlurV, kGlslTwinV, true},
  };
  const int n = static_cast<int>(g.weights.size() / 2);
  for (const Axis& a : axes) {
    glsl::CompileResult shader = load_glsl(a.glsl_file, a.glsl_builtin);
    if (!shader) return plan_failure(shader.message());
    std::map<std::string, std::string, std::less<>> files;
    if (!a.twin_file.empty()) files.emplace(std::string(a.twin_builtin), a.twin_file);
    ListingResult twin = glow_listing(a.twin_builtin, files, params.listing_options);
    if (!twin) return plan_failure(twin.message());
    for (const glsl::Sampler& s : shader->samplers)
      if (s.stage != 0)
        return plan_failure(
            fmt::format("{}: error: sampler '{}' is stage {}; the blur pass binds its "
                        "source to stage 0 only\n",
                        shader->file, s.name, s.stage));
    PassDesc p;
    p.name = a.name;
    p.draw.vertex_program = *vs;
    p.draw.pixel_program = *twin;
    // oT0 = uv · c4 + c0: the quad uv plus half a texel, so vTexCoord (t0) is a texel centre.
    p.draw.vs_constants.f = {{float(0.5 / w), float(0.5 / h), 0, 0},
                             {},
                             {},
                             {},
                             {1, 1, 1, 1},
                             {1, 1, 1, 1},
                             {1, 1, 1, 1},
                             {1, 1, 1, 1}};
    pass::SamplerState sampler;
    sampler.filter = pass::Filter::Point;
    sampler.address_u = sampler.address_v = pass::AddressMode::Clamp;
    bind_reads(p, 0, a.source, sampler, 1, false);
    p.target = a.target;
    p.draw.pixel_spirv = std::make_shared<const std::vector<uint32_t>>(std::move(shader->spirv));
    p.glsl_file = shader->file;
    p.analytic = AnalyticForm::Kernel;
    for (int k = -n; k <= n; ++k) {
      KernelTap t;
      t.stage = 0;
      t.offset = {0.5 / w, 0.5 / h};
      t.offset[a.vertical ? 1 : 0] += k * g.step;
      const double wk = g.weights[static_cast<size_t>(k + n)];
      t.weight = {wk, wk, wk, wk};
      p.kernel.push_back(t);
      if (!a.vertical) plan.taps.push_back({static_cast<int>(std::lround(k * g.step * w)), wk});
    }
    graph.passes.push_back(std::move(p));
  }
  plan.glow_width = w;
  plan.glow_height = h;
  plan.blur_passes_per_axis = 1;
  if (ir::Status checked = check_graph(graph); !checked) return plan_failure(checked.message());
  return plan;
}

std::vector<std::string> glsl_blur_warnings(const GlslBlurParams& g) {
  double sum = 0;
  for (double w : g.weights) sum += w;
  std::vector<std::string> out;
  if (std::isfinite(sum) && sum > 0 && std::abs(sum - 1) > 1e-9) {
    const double both = sum * sum; // x, then y: the sum scales the image twice
    out.push_back(fmt::format("kernel weights sum to {:.6g}: the blur is {:.3g} % {} than its "
                              "source ({:.4g} after both axes)",
                              sum, std::abs(both - 1) * 100, both < 1 ? "darker" : "brighter",
                              both));
  }
  return out;
}

} // namespace tierlift::effects
