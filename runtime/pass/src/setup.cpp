// RunRequest → Pass: constants into the stages' banks, inputs, textures read once.
#include "tierlift/pass/setup.h"

#include <fmt/format.h>
#include <map>
#include <new>

#include "program_reads.h"
#include "tierlift/image/builtin.h"
#include "tierlift/image/io.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/profile.h"
#include "tierlift/pass/input_sources.h"
#include "tierlift/pass/mip_chain.h"

namespace tierlift::pass {
namespace {

bool applies(StageMask m, ir::ShaderStage stage) {
  return m == StageMask::Both || (m == StageMask::Vertex) == (stage == ir::ShaderStage::Vertex);
}

void apply_constant(ConstantBank& bank, const ConstSetting& c) {
  switch (c.file) {
  case ir::RegFile::Const:
    if (bank.f.size() <= c.index) bank.f.resize(c.index + 1, Vec4{0, 0, 0, 0});
    bank.f[c.index] = c.f;
    break;
  case ir::RegFile::ConstInt: bank.i[c.index] = c.i; break;
  default: bank.b[c.index] = c.b; break;
  }
}

bool given(const std::vector<ConstSetting>& list, ir::ShaderStage stage, ir::RegFile f,
           uint32_t index) {
  for (const auto& c : list)
    if (applies(c.stage, stage) && c.file == f && c.index == index) return true;
  return false;
}

std::string_view stage_prefix(ir::ShaderStage s) {
  return s == ir::ShaderStage::Vertex ? "vs" : "ps";
}

// Constants of one stage; an error for every register read but neither given nor def'd.
bool build_constants(const ir::Program& program, const std::vector<ConstSetting>& list,
                     ConstantBank& bank, ir::DiagnosticSink& diags) {
  const ir::ShaderStage stage = program.stage();
  for (const auto& c : list)
    if (applies(c.stage, stage)) apply_constant(bank, c);
  bool ok = true;
  const ir::FoldedDefs defs = ir::fold_defs(program);
  std::vector<detail::RegRead> relative;
  for (const auto& r : detail::constant_reads(program, &relative)) {
    if (given(list, stage, r.file, r.index) || defs.find(r.file, r.index)) continue;
    std::string reg = ir::register_name(r.file, r.index);
    std::string example = r.file == ir::RegFile::ConstBool ? "true" : "x,y,z,w";
    if (r.file == ir::RegFile::ConstInt) example = "a,b,c,d";
    diags.error(r.loc, "constant-not-set",
                fmt::format("{} is read but neither given nor defined; pass --const {}:{}={}", reg,
                            stage_prefix(stage), reg, example));
    ok = false;
  }
  for (const auto& r : relative)
    diags.warning(r.loc, "constant-relative",
                  fmt::format("relative read based at {}: registers it reaches that are "
                              "neither given nor defined read 0",
                              ir::register_name(r.file, r.index)));
  return ok;
}

void set_sampler(const RunRequest& req, TextureBinding& b) {
  b.sampler.filter = req.filter;
  b.sampler.address_u = b.sampler.address_v = b.sampler.address_w = req.address;
  b.sampler.mip = req.mip;
  b.sampler.srgb = req.srgb_texture;
}

// How --texture names a sampler: sN for the pixel stage, vs:sN for the vertex stage's
// (is_vertex_sampler).
std::string sampler_flag(uint32_t sampler) {
  return is_vertex_sampler(sampler) ? fmt::format("vs:s{}", sampler - kVertexSampler0)
                                    : fmt::format("s{}", sampler);
}

// A 2D texture's levels: `levels` as given ("mips:"), or generated from its one image when
// the request asks for a chain; an error names the stage.
bool bind_2d(const RunRequest& req, const TextureSetting& t, bool given,
             std::vector<std::shared_ptr<const img::Image>> levels, TextureBinding& b,
             RunDiagnostics& diags) {
  if (!given && req.generated_levels != 1) levels = generate_mips(levels[0], req.generated_levels);
  ir::Result<TextureBinding> mb = mipmapped_binding(std::move(levels));
  if (!mb) {
    diags.other.error({}, "texture",
                      fmt::format("--texture {}: {}", sampler_flag(t.sampler), mb.message()));
    return false;
  }
  b.image = mb->image;
  b.levels = mb->levels;
  return true;
}

// The unbound-sampler and unused-texture warnings of one stage: `used` are the samplers its
// listing reads (numbered as the listing numbers them), `first` the number its s0 has in
// TextureSetting::sampler (0, or kVertexSampler0), `count` how many it has.
void warn_bindings(const RunRequest& req, const std::vector<detail::RegRead>& used,
                   const TextureBinding* bindings, uint32_t first, uint32_t count,
                   ir::DiagnosticSink& sink, RunDiagnostics& diags) {
  const char* listing = first == 0 ? "pixel" : "vertex";
  for (const auto& r : used)
    if (r.index >= count || !bindings[r.index].image)
      sink.warning(r.loc, "unbound-sampler",
                   fmt::format("sampler {} has no texture (--texture {}=...); it reads "
                               "(0,0,0,1)",
                               r.index, sampler_flag(first + r.index)));
  for (const TextureSetting& t : req.textures) {
    if (t.sampler < first || t.sampler >= first + count) continue;
    bool read = false;
    for (const auto& r : used) read = read || first + r.index == t.sampler;
    if (!read)
      diags.other.warning({}, "unused-texture",
                          fmt::format("--texture {}: the {} listing never samples s{}",
                                      sampler_flag(t.sampler), listing, t.sampler - first));
  }
}

bool bind_textures(const RunRequest& req, Pass& pass, RunDiagnostics& diags) {
  std::map<std::string, std::shared_ptr<const img::Image>> loaded; // one load per source
  bool ok = true;
  // The image of one source, loaded once; null after reporting why it could not be.
  auto load = [&](uint32_t sampler, const std::string& source) {
    auto it = loaded.find(source);
    if (it != loaded.end()) return it->second;
    img::ImageResult r = img::load_texture(source);
    if (!r) {
      // Could not be read at all (missing, a folder, over the cap): an I/O error.
      bool missing = !img::is_builtin_spec(source) && img::is_io_error(r);
      const std::string_view rule = img::is_builtin_spec(source) ? kRuleTextureSpec
                                    : missing                    ? kRuleTextureMissing
                                                                 : std::string_view("texture");
      diags.other.error({}, std::string(rule),
                        fmt::format("--texture {}: {}", sampler_flag(sampler), r.message()));
      return std::shared_ptr<const img::Image>();
    }
    return loaded.emplace(source, std::make_shared<const img::Image>(std::move(r).value()))
        .first->second;
  };
  for (const TextureSetting& t : req.textures) {
    TextureBinding* bound = sampler_binding(pass, t.sampler);
    if (!bound) {
      diags.other.error({}, "texture",
                        fmt::format("sampler {} does not exist (s0..s15, vs:s0..vs:s3)",
                                    sampler_flag(t.sampler)));
      ok = false;
      continue;
    }
    TextureBinding& b = *bound;
    if (t.image) {
      ok = bind_2d(req, t, false, {t.image}, b, diags) && ok;
      set_sampler(req, b);
      continue;
    }
    const auto [shape, sources, given_levels] = layered_sources(t.source);
    std::vector<std::shared_ptr<const img::Image>> layers;
    for (const std::string& src : sources) layers.push_back(load(t.sampler, src));
    bool all = true;
    for (const auto& l : layers) all = all && l;
    if (!all) {
      ok = false;
      continue;
    }
    if (shape == TextureShape::Tex2D) {
      if (!bind_2d(req, t, given_levels, std::move(layers), b, diags)) {
        ok = false;
        continue;
      }
    } else {
      ir::Result<TextureBinding> lb = layered_binding(shape, std::move(layers));
      if (!lb) {
        diags.other.error({}, "texture",
                          fmt::format("--texture {}: {}", sampler_flag(t.sampler), lb.message()));
        ok = false;
        continue;
      }
      b.shape = shape;
      b.image = lb->image;
      b.layers = lb->layers;
    }
    set_sampler(req, b);
  }
  if (!ok) return false; // the load error says it all; no unbound-stage warnings on top
  const std::vector<detail::RegRead> none;
  warn_bindings(req, req.ps ? detail::sampler_reads(*req.ps) : none, pass.textures.data(), 0,
                kMaxSamplers, diags.ps, diags);
  warn_bindings(req, req.vs ? detail::sampler_reads(*req.vs) : none, pass.vertex_textures.data(),
                kVertexSampler0, kMaxVertexSamplers, diags.vs, diags);
  return ok;
}

void set_vertex_inputs(const RunRequest& req, Pass& pass, RunDiagnostics& diags) {
  const uint32_t pos = position_input(*req.vs);
  set_full_screen_quad(pass, pos);
  for (const RegisterSetting& a : req.attrs) {
    if (a.index == pos) {
      diags.other.warning({}, "attr-position",
                          fmt::format("--attr v{}: v{} is the position input and gets the quad's "
                                      "corners; the value is ignored",
                                      a.index, a.index));
      continue;
    }
    for (size_t corner = 0; corner < 4; ++corner)
      pass.vertices[corner].v[a.index] = a.quad_uv ? kQuadUV[corner] : a.value;
  }
  if (!req.inputs.empty())
    diags.other.warning({}, "input-ignored",
                        "--input is for runs without --vs; the vertex listing's outputs feed the "
                        "pixel stage instead");
}

void set_pixel_inputs(const RunRequest& req, Pass& pass, RunDiagnostics& diags) {
  for (const RegisterSetting& in : req.inputs) {
    if (in.file == ir::RegFile::Input)
      pass.constant_inputs.color[in.index] = in.value;
    else
      pass.constant_inputs.tex[in.index] = in.value;
  }
  if (!req.attrs.empty())
    diags.other.warning({}, "attr-ignored",
                        "--attr needs --vs; without a vertex listing it is ignored");
}

// Settings built in code rather than by the parsers may carry any index: refuse those
// the pass has no register for, instead of writing out of bounds.
bool check_indices(const RunRequest& req, RunDiagnostics& diags) {
  bool ok = true;
  auto refuse = [&](std::string what) {
    diags.other.error({}, "register", what + " does not exist");
    ok = false;
  };
  for (const auto& c : req.constants) {
    uint32_t limit = c.file == ir::RegFile::Const ? 4096 : 16;
    if (c.index >= limit) refuse(ir::register_name(c.file, c.index));
  }
  for (const auto& a : req.attrs)
    if (a.index >= 16) refuse(fmt::format("vertex input v{}", a.index));
  for (const auto& in : req.inputs)
    if (in.index >= (in.file == ir::RegFile::Input ? 2u : 8u))
      refuse("pixel input " + ir::register_name(in.file, in.index));
  for (const BumpSetting& b : req.bump_matrices)
    if (b.stage >= kMaxSamplers) refuse(fmt::format("texture stage {}", b.stage));
  return ok;
}

// The c# a stage can be given: the profile's count for a pixel listing (ps_1_x 8, ps_2_0
// 32); 256 for a vertex listing, as many as a Direct3D 9 device takes for any vertex profile
// (vs_1_1 guarantees 96, but relative reads reach further on every device since the GeForce3).
uint32_t settable_float_constants(const ir::Program& program) {
  return program.stage() == ir::ShaderStage::Vertex ? 256u
                                                    : ir::limits(program.profile).float_consts;
}

// A c# setting no stage of the run can hold (ps:c999) is refused: written nowhere, it
// would be ignored without a word.
bool check_constant_ranges(const RunRequest& req, RunDiagnostics& diags) {
  bool ok = true;
  for (const ConstSetting& c : req.constants) {
    if (c.file != ir::RegFile::Const) continue;
    bool held = false, applies_somewhere = false;
    std::string limits;
    for (const auto* program : {req.vs.get(), req.ps.get()}) {
      if (!program || !applies(c.stage, program->stage())) continue;
      applies_somewhere = true;
      const uint32_t count = settable_float_constants(*program);
      held = held || c.index < count;
      limits += fmt::format("{}{} has c0..c{}", limits.empty() ? "" : ", ",
                            ir::profile_name(program->profile), count - 1);
    }
    if (!applies_somewhere || held) continue;
    diags.other.error(
        {}, std::string(kRuleConstantRange),
        fmt::format("--const c{}: outside the constant registers ({})", c.index, limits));
    ok = false;
  }
  return ok;
}

// Each render target beyond oC0 needs a pixel program that writes its oC#: Vulkan leaves an
// attachment without a fragment output undefined, and D3D9 writes nothing defined either.
bool check_color_targets(const RunRequest& req, RunDiagnostics& diags) {
  if (req.color_targets < 1 || req.color_targets > 4) {
    diags.other.error({}, "targets",
                      fmt::format("{} render targets: D3D9 has 1 to 4", req.color_targets));
    return false;
  }
  for (uint32_t i = 1; i < req.color_targets; ++i) {
    bool written = false;
    if (req.ps)
      for (const ir::Instruction& in : req.ps->code)
        written =
            written || (in.dst && in.dst->file == ir::RegFile::ColorOut && in.dst->index == i);
    if (!written) {
      diags.other.error({}, "targets",
                        fmt::format("render target {} is asked for, but {} writes no oC{}", i,
                                    req.ps ? "the pixel listing" : "a pass without one", i));
      return false;
    }
  }
  return true;
}

// prepare_pass's work: its checks report into the sink of the listing they point into.
std::optional<Pass> prepare(const RunRequest& req, RunDiagnostics& diags) {
  if (!img::valid_size(req.width, req.height)) {
    diags.other.error(
        {}, "size",
        fmt::format("size {}x{} outside 1..{}", req.width, req.height, img::kMaxDimension));
    return std::nullopt;
  }
  Pass pass;
  bool ok = true;
  if (req.vs && req.vs->stage() != ir::ShaderStage::Vertex) {
    diags.vs.error(req.vs->version_loc, "stage", "--vs expects a vertex listing (vs_1_1, vs_2_0)");
    ok = false;
  }
  if (req.ps && req.ps->stage() != ir::ShaderStage::Pixel) {
    diags.ps.error(req.ps->version_loc, "stage", "--ps expects a pixel listing (ps_1_1 .. ps_2_0)");
    ok = false;
  }
  if (!ok || !check_indices(req, diags) || !check_constant_ranges(req, diags) ||
      !check_color_targets(req, diags))
    return std::nullopt;
  pass.vertex_program = req.vs;
  pass.pixel_program = req.ps;
  pass.conventions = req.conventions;
  pass.front_face = req.front_face;
  pass.color_targets = req.color_targets;
  pass.srgb_write = req.srgb_write;
  pass.depth_stencil = req.depth_stencil;
  if (req.vs) ok = build_constants(*req.vs, req.constants, pass.vs_constants, diags.vs) && ok;
  if (req.ps) ok = build_constants(*req.ps, req.constants, pass.ps_constants, diags.ps) && ok;
  ok = bind_textures(req, pass, diags) && ok;
  for (const BumpSetting& b : req.bump_matrices)
    pass.textures[b.stage].stage.bumpenv_mat = b.matrix;
  if (req.vs)
    set_vertex_inputs(req, pass, diags);
  else
    set_pixel_inputs(req, pass, diags);
  if (uses_quad_uv_stage(req)) set_quad_uv_stage(req, pass); // t# from the quad's uv
  if (!ok) return std::nullopt;
  return pass;
}

} // namespace

ir::Result<Pass> prepare_pass(const RunRequest& req) {
  RunDiagnostics diags;
  std::optional<Pass> pass;
  try { // a huge texture may not fit: running out of memory is an error, not a crash
    pass = prepare(req, diags);
  } catch (const std::bad_alloc&) {
    diags.other.error({}, "memory",
                      fmt::format("not enough memory for a {}x{} target and its textures",
                                  req.width, req.height));
  }
  if (!pass && !diags.has_errors()) // every refusal above reports; keep a Failure non-empty
    diags.other.error({}, "internal", "the pass could not be prepared");
  std::vector<ir::Diagnostic> all;
  auto take = [&](const ir::DiagnosticSink& sink, std::string_view listing) {
    for (ir::Diagnostic d : sink.all()) {
      d.subject = std::string(listing);
      all.push_back(std::move(d));
    }
  };
  take(diags.vs, kVsListing);
  take(diags.ps, kPsListing);
  for (const ir::Diagnostic& d : diags.other.all()) all.push_back(d);
  if (!pass) return ir::Failure{std::move(all)};
  ir::Result<Pass> out(std::move(*pass));
  for (ir::Diagnostic& d : all) out.add(std::move(d));
  return out;
}

void add_by_listing(RunDiagnostics& diags, const std::vector<ir::Diagnostic>& ds) {
  for (ir::Diagnostic d : ds) {
    ir::DiagnosticSink& sink = d.subject == kVsListing   ? diags.vs
                               : d.subject == kPsListing ? diags.ps
                                                         : diags.other;
    if (&sink != &diags.other) d.subject.clear();
    sink.add(std::move(d));
  }
}

std::vector<ProbeValue> read_probes(const img::Image& image,
                                    const std::vector<ProbePoint>& probes) {
  std::vector<ProbeValue> out;
  for (const ProbePoint& p : probes) {
    const float* px = image.at(p.x, p.y);
    out.push_back({p.x, p.y, {px[0], px[1], px[2], px[3]}});
  }
  return out;
}

// "cube:F0,…,F5" or "volume:S0,…": the shape and its layers' sources; Tex2D otherwise.
LayeredSources layered_sources(const std::string& source) {
  TextureShape shape = TextureShape::Tex2D;
  std::string rest;
  if (source.rfind("cube:", 0) == 0) {
    shape = TextureShape::Cube;
    rest = source.substr(5);
  } else if (source.rfind("volume:", 0) == 0) {
    shape = TextureShape::Volume;
    rest = source.substr(7);
  } else if (source.rfind("mips:", 0) == 0) {
    rest = source.substr(5);
  } else {
    return {shape, {source}};
  }
  std::vector<std::string> parts;
  size_t from = 0;
  for (size_t comma; (comma = rest.find(',', from)) != std::string::npos; from = comma + 1)
    parts.push_back(rest.substr(from, comma - from));
  parts.push_back(rest.substr(from));
  return {shape, parts, source.rfind("mips:", 0) == 0};
}

} // namespace tierlift::pass
