#include "diff_run.h"

#include <cmath>
#include <limits>
#include <span>

#include <fmt/format.h>

#include "tierlift/corpus/cases.h"
#include "tierlift/corpus/undefined_reads.h"
#include "tierlift/effects/graph/device.h"
#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/effects/graph/single_pass.h"
#include "tierlift/image/compare.h"
#include "tierlift/ir/profile.h"
#include "tierlift/pass/setup.h"

namespace tierlift::corpus {
namespace {

// splitmix64: the project's seeded generator (img::builtin_noise uses the same).
struct Rng {
  uint64_t state;
  uint64_t next() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  uint32_t below(uint32_t n) { return static_cast<uint32_t>(next() % n); }
};

// NUMERICS.md's special values: zeros, ±1, infinities, NaN, denormals, large magnitudes.
constexpr float kSpecial[] = {0.0f,
                              -0.0f,
                              1.0f,
                              -1.0f,
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              std::numeric_limits<float>::quiet_NaN(),
                              1e-40f, // denormal
                              -1e-40f,
                              1e30f,
                              -1e30f,
                              65504.0f};

// Set 0: ordinary values only; set 1: special values only; later sets: a quarter special.
// Ordinary values are multiples of 1/64 in [-2, 2], exact in every format on the way.
float value(Rng& rng, unsigned set) {
  const bool special = set == 1 || (set >= 2 && rng.below(4) == 0);
  if (special) return kSpecial[rng.below(std::size(kSpecial))];
  return (static_cast<float>(rng.below(257)) - 128.0f) / 64.0f;
}
pass::Vec4 vec(Rng& rng, unsigned set) {
  return {value(rng, set), value(rng, set), value(rng, set), value(rng, set)};
}
// Texture coordinates stay in [0, 1]: addressing at extreme coordinates is a documented
// difference between the devices (docs/stage-states.md), not what this run looks for.
pass::Vec4 coordinate(Rng& rng) {
  auto c = [&] { return static_cast<float>(rng.below(65)) / 64.0f; };
  return {c(), c(), c(), 1.0f};
}

// The stages a program samples and the texture type each reads: ps_2_0 and later (and vs_3_0,
// whose samplers are the vertex stage's) declare it (dcl_2d, dcl_cube, dcl_volume); ps_1_x reads a
// cube with texm3x3tex, texm3x3spec and texm3x3vspec (D3D9's texture-address instructions for
// environment maps), a 2D texture otherwise.
std::vector<std::pair<uint32_t, ir::SamplerType>> sampled_stages(const ir::Program& p) {
  std::vector<std::pair<uint32_t, ir::SamplerType>> out;
  if (ir::is_sm2_or_later(p.profile)) { // ps_2_0, ps_2_x, ps_3_0 declare their samplers
    for (const ir::Declaration& d : p.decls)
      if (d.reg.file == ir::RegFile::Sampler &&
          (d.sampler_type == ir::SamplerType::Tex2D || d.sampler_type == ir::SamplerType::Cube ||
           d.sampler_type == ir::SamplerType::Volume))
        out.emplace_back(d.reg.index, d.sampler_type);
  } else if (ir::is_pixel(p.profile)) {
    for (uint32_t s = 0; s < ir::limits(p.profile).samplers; ++s)
      out.emplace_back(s, ir::SamplerType::Tex2D);
    for (const ir::Instruction& ins : p.code)
      if ((ins.op == ir::Opcode::TexM3x3Tex || ins.op == ir::Opcode::TexM3x3Spec ||
           ins.op == ir::Opcode::TexM3x3VSpec) &&
          ins.dst && ins.dst->index < out.size())
        out[ins.dst->index].second = ir::SamplerType::Cube;
  }
  return out;
}

// A generated texture of the type: one 8×8 noise image, or six (a cube) or four slices (a
// volume) of them, each with its own seed (pass::layered_sources' syntax).
std::string texture_source(Rng& rng, ir::SamplerType type) {
  auto noise = [&] { return fmt::format("builtin:noise:8x8:{}", rng.below(1000) + 1); };
  if (type == ir::SamplerType::Tex2D) return noise();
  const bool cube = type == ir::SamplerType::Cube;
  std::string s = cube ? "cube:" : "volume:";
  // Appended piece by piece, not (k ? "," : "") + noise(): GCC 12 -O3 reports a false
  // -Wrestrict in the inlined concatenation (GCC bug 105651), failing a Release build.
  for (int k = 0; k < (cube ? 6 : 4); ++k) {
    if (k) s += ',';
    s += noise();
  }
  return s;
}

// A vertex shader's oPos usually comes from constants (a world-view-projection matrix): with
// generated constants the quad lands off the target, and two devices that agree on an empty
// image prove nothing. The run draws a copy whose oPos writes go to a temporary register the
// shader never uses, followed by `mov oPos, v<position>`: the quad covers the target and what
// the shader computes for oD0 is on every pixel. Programs with subroutines (where "the end"
// is not the last statement) or no position input declared are drawn as they are.
ir::Program with_quad_position(const ir::Program& p) {
  const uint32_t position = pass::position_input(p);
  bool declared = false, used[256] = {};
  uint32_t last_seq = 0;
  for (const ir::Declaration& d : p.decls) {
    declared |= d.reg.file == ir::RegFile::Input && d.reg.index == position;
    last_seq = std::max(last_seq, d.seq);
  }
  for (const ir::ConstDef& d : p.defs) last_seq = std::max(last_seq, d.seq);
  for (const ir::Instruction& ins : p.code) {
    if (ins.op == ir::Opcode::Ret || ins.op == ir::Opcode::Label) return p;
    if (ins.dst && ins.dst->file == ir::RegFile::Temp && ins.dst->index < 256)
      used[ins.dst->index] = true;
    for (const ir::SrcOperand& s : ins.src)
      if (s.file == ir::RegFile::Temp && s.index < 256) used[s.index] = true;
    last_seq = std::max(last_seq, ins.seq);
  }
  uint32_t spare = ir::limits(p.profile).temps;
  while (spare > 0 && used[spare - 1]) --spare;
  if (!declared || spare == 0) return p;
  ir::Program q = p;
  for (ir::Instruction& ins : q.code)
    if (ins.dst && ins.dst->file == ir::RegFile::RastOut && ins.dst->index == ir::kRastPos) {
      ins.dst->file = ir::RegFile::Temp;
      ins.dst->index = spare - 1;
    }
  ir::Instruction mov;
  mov.op = ir::Opcode::Mov;
  mov.dst = ir::DstOperand{ir::RegFile::RastOut, ir::kRastPos, ir::kFullMask, {}};
  ir::SrcOperand from;
  from.file = ir::RegFile::Input;
  from.index = position;
  mov.src.push_back(from);
  mov.seq = last_seq + 1;
  q.code.push_back(std::move(mov));
  return q;
}

// `drawn`: the program as every set draws it (one object, so the Vulkan device compiles it
// once: effects::VulkanPassOptions::reuse_programs).
pass::RunRequest request(const ir::Program& program,
                         const std::shared_ptr<const ir::Program>& drawn, const StageOptions& o,
                         Rng& rng, unsigned set) {
  pass::RunRequest r;
  const ir::ProfileLimits& lim = ir::limits(program.profile);
  r.width = r.height = o.size;
  r.format = img::Format::RGBA32F;
  r.threads = 1; // the workers are the parallelism
  for (uint32_t i = 0; i < lim.float_consts; ++i)
    r.constants.push_back({pass::StageMask::Both, ir::RegFile::Const, i, vec(rng, set), {}, false});
  for (uint32_t i = 0; i < lim.int_consts; ++i) {
    pass::ConstSetting c{pass::StageMask::Both, ir::RegFile::ConstInt, i, {}, {}, false};
    c.i = {static_cast<int32_t>(rng.below(4)), static_cast<int32_t>(rng.below(4)),
           static_cast<int32_t>(rng.below(4)) - 1, 0};
    r.constants.push_back(c);
  }
  for (uint32_t i = 0; i < lim.bool_consts; ++i)
    r.constants.push_back(
        {pass::StageMask::Both, ir::RegFile::ConstBool, i, {}, {}, rng.below(2) == 1});
  if (program.stage() == ir::ShaderStage::Vertex) {
    r.vs = drawn;
    const uint32_t position = pass::position_input(program);
    const std::vector<uint32_t> uv = pass::texcoord_inputs(program);
    for (uint32_t v = 0; v < lim.inputs; ++v) {
      if (v == position) continue;
      const bool is_uv = std::find(uv.begin(), uv.end(), v) != uv.end();
      r.attrs.push_back({ir::RegFile::Input, v, vec(rng, set), is_uv});
    }
    // vs_3_0's texldl reads the vertex stage's own samplers (vertex texture fetch, NUMERICS.md
    // F14): a generated texture at each one it declares, as a pixel program gets at its s#.
    for (const auto& [s, type] : sampled_stages(program))
      r.textures.emplace_back(pass::kVertexSampler0 + s, texture_source(rng, type));
  } else {
    r.ps = drawn;
    // ps_3_0 reads its v# by semantic (ir/sm3_interface.h): color0-1 are the colour inputs,
    // texcoord0-7 the coordinates, as in ps_2_0.
    const bool sm3 = ir::is_sm3(program.profile);
    for (uint32_t v = 0; v < (sm3 ? 2u : lim.inputs); ++v)
      r.inputs.push_back({ir::RegFile::Input, v, vec(rng, set), false});
    for (uint32_t t = 0; t < (sm3 ? 8u : lim.texcoords); ++t)
      r.inputs.push_back({ir::RegFile::Texture, t, coordinate(rng), false});
    for (const auto& [s, type] : sampled_stages(program))
      r.textures.emplace_back(s, texture_source(rng, type));
  }
  r.filter = set % 2 == 0 ? pass::Filter::Point : pass::Filter::Linear;
  r.address = pass::AddressMode::Clamp;
  return r;
}

// One device's image of the graph, or why not.
ir::Result<img::Image> draw(const effects::EffectGraph& graph, effects::PassDevice& device) {
  effects::ImageMap images;
  const std::string target(effects::kSinglePassTarget);
  ir::Result<effects::GraphRun> run = effects::run_graph_reading(graph, device, images, {target});
  if (!run) return run.failure();
  return std::move(images.at(target));
}

std::string why(const std::vector<ir::Diagnostic>& ds) {
  std::string out;
  for (const ir::Diagnostic& d : ds) {
    if (d.severity == ir::Severity::Warning) continue;
    if (!out.empty()) out += "; ";
    out += d.message;
  }
  return out;
}

} // namespace

StageResult differential_run(const ir::Program& program, const std::string& id,
                             const StageOptions& o, std::optional<Difference>& difference) {
  StageResult s{std::string(kStageDiff), Verdict::Pass, {}, 0};
  Rng rng{o.seed ^ fnv1a64(id)};
  effects::CpuPassDevice cpu(1);
  // One compile and one pipeline for all K sets: their constants go through the uniform
  // block (the images are those a pipeline per set would draw).
  std::unique_ptr<effects::PassDevice> vk =
      effects::make_vulkan_pass_device(*o.device, {.reuse_programs = o.one_pipeline_per_case});
  const auto drawn = std::make_shared<const ir::Program>(
      program.stage() == ir::ShaderStage::Vertex ? with_quad_position(program) : program);
  for (unsigned set = 0; set < o.input_sets; ++set) {
    const pass::RunRequest req = request(program, drawn, o, rng, set);
    ir::Result<pass::Pass> made = pass::prepare_pass(req);
    // A Vulkan device that filters cube maps across face edges refuses LINEAR cube reads
    // (NUMERICS.md rule T4): there cubes are read with POINT filtering on every set, in both
    // stages (a vs_3_0 reads its own samplers, F14).
    if (made && !o.device->cube_faces_filtered_alone())
      for (std::span<pass::TextureBinding> stage :
           {std::span<pass::TextureBinding>(made->textures),
            std::span<pass::TextureBinding>(made->vertex_textures)})
        for (pass::TextureBinding& b : stage)
          if (b.shape == pass::TextureShape::Cube) b.sampler.filter = pass::Filter::Point;
    ir::Result<effects::EffectGraph> graph =
        made ? effects::single_pass_graph(*made, req.width, req.height, req.format)
             : ir::Result<effects::EffectGraph>(made.failure());
    if (!graph) {
      s.verdict = Verdict::Fail;
      s.message = fmt::format("input set {}: {}", set, why(graph.diagnostics()));
      return s;
    }
    ir::Result<img::Image> a = draw(*graph, cpu);
    ir::Result<img::Image> b = draw(*graph, *vk);
    if (!a || !b) {
      s.verdict = Verdict::Fail;
      s.message = fmt::format("input set {}: {}{}", set, a ? "" : "cpu: " + why(a.diagnostics()),
                              b ? "" : " vulkan: " + why(b.diagnostics()));
      return s;
    }
    ir::Result<img::Comparison> c = img::compare(*a, *b);
    if (!c) {
      s.verdict = Verdict::Fail;
      s.message = c.message();
      return s;
    }
    img::Verdict v = img::judge(*c, req.format);
    if (v.pass) continue;
    // NUMERICS.md rule 38: pixels whose program samples at a non-finite coordinate, or takes
    // sincos outside [−π, π], are undefined in Direct3D 9 and not compared. Every pixel of this run
    // has the same inputs, so the rule takes the whole image of this input set or none of it.
    std::string read = non_finite_read(*made);
    if (read.empty()) read = sincos_out_of_range(*made);
    if (!read.empty()) {
      s.message += fmt::format("{}input set {} not compared: undefined in D3D9 ({})",
                               s.message.empty() ? "" : "; ", set, read);
      continue;
    }
    Difference d;
    d.input_set = set;
    d.x = c->worst_x;
    d.y = c->worst_y;
    d.channel = c->worst_channel;
    d.cpu = a->at(d.x, d.y)[d.channel];
    d.vulkan = b->at(d.x, d.y)[d.channel];
    d.summary = v.summary;
    s.verdict = Verdict::Fail;
    s.message = fmt::format("input set {}: pixel {},{} {}: interpreter {} vulkan {} ({})", set, d.x,
                            d.y, "rgba"[d.channel], d.cpu, d.vulkan, v.summary);
    difference = d;
    return s;
  }
  return s;
}

} // namespace tierlift::corpus
