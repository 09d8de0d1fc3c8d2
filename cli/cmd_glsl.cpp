// tierlift glsl FILE: a GLSL fragment shader compiled by glslang (in-process), checked by
// spirv-val, its interface listed; --spirv writes the module, -o draws it over an image on
// the Vulkan device (docs/glsl.md, "tierlift glsl").
#include <fmt/format.h>

#include "commands.h"
#include "flags/run_flags.h"
#include "front_end.h"
#include "report.h"
#include "run_output.h"
#include "tierlift/effects/glow/glsl_pass.h"
#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/effects/graph/vulkan_device.h"
#include "tierlift/effects/scenes/default_scene.h"
#include "tierlift/image/io.h"
#include "tierlift/ir/result_diagnostics.h"

namespace tierlift::cli {
namespace {

constexpr std::string_view kBuiltinNeon = "builtin:neon";

struct Flags {
  std::string file, image{kBuiltinNeon}, size = "512x512", format = "rgba32f", filter = "point";
  std::string output, spirv, gpu;
  bool json = false;
};

std::string interface_text(const glsl::FragmentShader& s) {
  std::string t = fmt::format("{}: ok: {} words of SPIR-V, valid for Vulkan 1.1 (spirv-val)\n",
                              s.file, s.spirv.size());
  for (const glsl::Sampler& x : s.samplers)
    t += fmt::format("  sampler {}: stage s{} (binding {})\n", x.name, x.stage,
                     x.stage + glsl::kFirstSamplerBinding);
  for (const glsl::Input& x : s.inputs)
    t +=
        fmt::format("  input {}: location {} (oT{} of the quad)\n", x.name, x.location, x.location);
  return t;
}

// The image every sampler reads: builtin:neon at --size, or a PNG/PFM file (its own size).
img::ImageResult load_image(const Flags& f, uint32_t w, uint32_t h) {
  if (f.image == kBuiltinNeon) return effects::make_default_scene(w, h);
  return img::read_image(f.image);
}

int run(const Flags& f) {
  Report report("glsl", f.json);
  for (const std::string* out : {&f.output, &f.spirv}) {
    if (out->empty()) continue;
    std::string why = check_output(*out, {f.file, f.image}, f.json).message();
    if (why.empty() && *out == "-") why = "give -o and --spirv a file";
    if (!why.empty()) {
      report.error(*out == "-" ? "usage" : "io", why, *out);
      return report.finish(kExitUsage);
    }
  }
  const ir::Result<std::array<uint32_t, 2>> size = parse_size(f.size);
  const auto format = img::parse_format(f.format);
  const auto filter = parse_filter(f.filter);
  if (!size || !format || !filter) {
    report.error("usage", !size ? size.message()
                          : !format
                              ? fmt::format("--format '{}': expected rgba8, rgba16f or "
                                            "rgba32f",
                                            f.format)
                              : fmt::format("--filter '{}': expected point or linear", f.filter));
    return report.finish(kExitUsage);
  }

  glsl::CompileResult compiled = glsl::compile_fragment_file(f.file);
  if (!compiled) {
    const bool io = ir::failed_with(compiled, glsl::kIoRule);
    if (f.json)
      report.error(io ? "io" : "glsl", compiled.message(), f.file);
    else
      fmt::print(stderr, "{}", compiled.message());
    return report.finish(io ? kExitUsage : kExitInvalid);
  }
  const glsl::FragmentShader& shader = *compiled;
  nlohmann::json& result = report.result();
  result["spirv_words"] = shader.spirv.size();
  result["samplers"] = nlohmann::json::array();
  for (const glsl::Sampler& s : shader.samplers)
    result["samplers"].push_back({{"name", s.name}, {"stage", s.stage}});
  result["inputs"] = nlohmann::json::array();
  for (const glsl::Input& s : shader.inputs)
    result["inputs"].push_back({{"name", s.name}, {"location", s.location}});
  if (!f.json) fmt::print("{}", interface_text(shader));

  std::optional<img::Image> image;
  std::optional<effects::EffectPlan> plan;
  if (!f.output.empty()) {
    img::ImageResult loaded = load_image(f, (*size)[0], (*size)[1]);
    if (!loaded) {
      const bool io = img::is_io_error(loaded);
      report.error(io ? "io" : "image", loaded.message(), f.image);
      return report.finish(io ? kExitUsage : kExitInvalid);
    }
    image = std::move(*loaded);
    effects::PlanResult built =
        effects::build_glsl_pass(shader, image->width, image->height, *format, *filter);
    if (!built) {
      if (f.json)
        report.error("glsl", built.message(), f.file);
      else
        fmt::print(stderr, "{}", built.message());
      return report.finish(kExitInvalid);
    }
    plan = std::move(*built);
  }
  if (!f.spirv.empty()) {
    const std::string_view bytes(reinterpret_cast<const char*>(shader.spirv.data()),
                                 shader.spirv.size() * sizeof(uint32_t));
    if (std::string why = write_output(f.spirv, bytes); !why.empty()) {
      report.error("io", why, f.spirv);
      return report.finish(kExitUsage);
    }
  }
  if (f.output.empty()) return report.finish(kExitOk);

  const ir::Result<vulkan::Device*> device = effects::vulkan_device(f.gpu);
  if (!device) {
    report.error("device", device.message());
    return report.finish(kExitUsage);
  }
  std::unique_ptr<effects::PassDevice> vk = effects::make_vulkan_pass_device(**device);
  effects::ImageMap images;
  images.emplace(std::string(effects::kSceneTexture), std::move(*image));
  const ir::Result<effects::GraphRun> run = effects::run_graph(plan->graph, *vk, images);
  if (!run) {
    report.error("device", run.message(), f.file);
    return report.finish(kExitInvalid);
  }
  std::string warning;
  const img::Image& out = images.at(std::string(effects::kFinalTexture));
  if (std::string why = write_run_output(f.output, out, &warning); !why.empty()) {
    report.error("io", why, f.output);
    return report.finish(kExitUsage);
  }
  if (!warning.empty()) report.warning("output", warning, f.output);
  result["output"] = f.output;
  result["device"] = effects::vulkan_device_name(**device);
  result["ms"] = run->total_ms;
  if (!f.json)
    fmt::print("wrote {} ({}x{}, {}, drawn on {} in {:.1f} ms)\n", f.output, out.width, out.height,
               img::format_name(out.format), effects::vulkan_device_name(**device), run->total_ms);
  return report.finish(kExitOk);
}

} // namespace

void register_glsl_command(CLI::App& app) {
  auto f = std::make_shared<Flags>();
  CLI::App* sub = app.add_subcommand(
      "glsl", "Compile a GLSL fragment shader with glslang (checked by spirv-val) and draw it");
  sub->add_option("file", f->file, "GLSL fragment shader (legacy 1.10 or Vulkan 4.50)")->required();
  sub->add_option("-o,--output", f->output,
                  "Draw the shader over a full-screen quad on the Vulkan device and write the "
                  "result (.png, or .pfm for float values)");
  sub->add_option("--spirv", f->spirv, "Write the validated SPIR-V module");
  sub->add_option("--image", f->image,
                  "What every sampler reads: a PNG or PFM file, or builtin:neon (default)");
  sub->add_option("--size", f->size, "The size of builtin:neon, WxH (default 512x512)");
  sub->add_option("--format", f->format, "Texture format: rgba8, rgba16f, rgba32f (default)");
  sub->add_option("--filter", f->filter, "Sampler filter: point (default) or linear");
  sub->add_option("--gpu", f->gpu, "Pick the Vulkan device whose name contains this text");
  sub->add_flag("--json", f->json, "Print one JSON document (docs/command-line.md)");
  set_action(sub, [f] { return run(*f); });
}

} // namespace tierlift::cli
