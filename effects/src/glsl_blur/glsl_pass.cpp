// A user's GLSL fragment shader as a one-pass graph (glsl_pass.h).
#include "tierlift/effects/glow/glsl_pass.h"

#include <fmt/format.h>

#include "tierlift/effects/glow/builtin_listing.h"

#include "tierlift/assembly/load.h"
#include "tierlift/ir/result_diagnostics.h"

namespace tierlift::effects {
namespace {

constexpr std::string_view kQuadVs = "glow/quad4_coords.vsh";

// The twin the Vulkan device takes the pass's interface from: t0..t3 and each sampled stage
// read, so the pair's linking keeps every coordinate the vertex stage writes and every
// sampler binding. Its own result is never drawn (the GLSL's SPIR-V is).
std::string twin_text(const glsl::FragmentShader& shader) {
  std::string t = "ps_2_0\n";
  for (uint32_t k = 0; k < kGlslPassInputs; ++k) t += fmt::format("dcl t{}\n", k);
  for (const glsl::Sampler& s : shader.samplers) t += fmt::format("dcl_2d s{}\n", s.stage);
  t += "mov r0, t0\nadd r0, r0, t1\nadd r0, r0, t2\nadd r0, r0, t3\n"; // one t# per instruction
  for (const glsl::Sampler& s : shader.samplers)
    t += fmt::format("texld r1, t0, s{0}\nadd r0, r0, r1\n", s.stage);
  t += "mov oC0, r0\n";
  return t;
}

ListingResult assemble(std::string text, const std::string& name) {
  ir::SourceManager sources;
  const uint32_t file = sources.add(name, std::move(text));
  assembly::LoadOptions options;
  options.warnings = false;
  assembly::Loaded r = assembly::load_listing(file, sources, options);
  if (!r.program)
    return ir::fail(name, "listing", ir::render_text(r.program.diagnostics(), sources));
  return std::make_shared<const ir::Program>(std::move(r.program).value());
}

} // namespace

PlanResult build_glsl_pass(const glsl::FragmentShader& shader, uint32_t width, uint32_t height,
                           img::Format format, pass::Filter filter) {
  EffectPlan plan;
  if (!img::valid_size(width, height))
    return plan_failure(
        fmt::format("size {}x{}: expected 1..{} each", width, height, img::kMaxDimension));
  for (const glsl::Input& in : shader.inputs)
    if (in.location >= kGlslPassInputs)
      return plan_failure(fmt::format("{}: error: input '{}' is at location {}; the pass's vertex "
                                      "stage writes texture coordinates at locations 0..{} only\n",
                                      shader.file, in.name, in.location, kGlslPassInputs - 1));
  ListingResult vs = builtin_listing(kQuadVs);
  if (!vs) return plan_failure(vs.message());
  ListingResult twin = assemble(twin_text(shader), "(the GLSL pass's generated ps_2_0 twin)");
  if (!twin) return plan_failure(twin.message());
  EffectGraph& g = plan.graph;
  g.textures.push_back({std::string(kSceneTexture), width, height, format, true});
  g.textures.push_back({std::string(kFinalTexture), width, height, format, false});
  PassDesc p;
  p.name = "glsl";
  p.draw.vertex_program = *vs;
  p.draw.pixel_program = *twin;
  // oTk = uv · c(k+4) + ck: the quad uv plus half a texel, for k = 0..3.
  const pass::Vec4 half{float(0.5 / width), float(0.5 / height), 0, 0}, one{1, 1, 1, 1};
  p.draw.vs_constants.f = {half, half, half, half, one, one, one, one};
  pass::SamplerState sampler;
  sampler.filter = filter;
  sampler.address_u = sampler.address_v = pass::AddressMode::Clamp;
  for (const glsl::Sampler& s : shader.samplers)
    bind_reads(p, s.stage, kSceneTexture, sampler, 1, false);
  p.target = std::string(kFinalTexture);
  p.draw.pixel_spirv = std::make_shared<const std::vector<uint32_t>>(shader.spirv);
  p.glsl_file = shader.file;
  g.passes.push_back(std::move(p));
  plan.glow_width = width;
  plan.glow_height = height;
  if (ir::Status checked = check_graph(g); !checked) return plan_failure(checked.message());
  return plan;
}

} // namespace tierlift::effects
