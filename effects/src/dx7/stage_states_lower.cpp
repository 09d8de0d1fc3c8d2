// Lowering of validated texture-stage states into a vs.1.1 + ps.1.1 pair (stage_states.h).
// Each stage's colour operation becomes one instruction writing r0.rgb and its alpha
// operation one writing r0.a, in stage order, colour first: a colour operation never writes
// alpha, so the alpha operation of the same stage still reads the previous stage's alpha as
// CURRENT, as in the fixed-function cascade. Direct3D 7 saturates every stage result to
// [0, 1]; the ps.1.x registers clamp to [-1, 1] (the tier runs with MaxPixelShaderValue 1),
// which is the same thing for the non-negative results of MODULATE, ADD, SELECTARG and
// MODULATEALPHA_ADDCOLOR on [0, 1] inputs. SUBTRACT and ADDSIGNED can go negative and carry
// `_sat`.
#include <fmt/format.h>

#include "tierlift/assembly/load.h"
#include "tierlift/effects/glow/stage_states.h"
#include "tierlift/ir/result_diagnostics.h"

namespace tierlift::effects::tss {
namespace {

bool reads(const std::optional<Operation>& o, Arg a) {
  if (!o) return false;
  for (Arg x : o->args)
    if (x == a) return true;
  return false;
}

// Direct3D's defaults where a stage leaves a state unset: stage 0's alpha is SELECTARG1
// TEXTURE; every later stage's alpha is DISABLE (the current alpha passes on).
Operation alpha_of(const Stage& s, uint32_t n) {
  if (s.alpha) return *s.alpha;
  Operation o;
  if (n == 0) {
    o.op = Op::SelectArg1;
    o.args = {Arg::Texture};
  }
  return o;
}

bool stage_enabled(const StageStates& st, uint32_t n) {
  if (n >= st.stages.size()) return false;
  const Stage& s = st.stages[n];
  if (n == 0 && !s.color) return true; // Direct3D's default stage 0: MODULATE TEXTURE CURRENT
  return s.color && s.color->op != Op::Disable;
}

Operation color_of(const Stage& s, uint32_t n) {
  if (s.color) return *s.color;
  Operation o;
  if (n == 0) {
    o.op = Op::Modulate;
    o.args = {Arg::Texture, Arg::Current};
  }
  return o;
}

std::string reg(Arg a, uint32_t n) {
  switch (a) {
  case Arg::Current: return n == 0 ? "v0" : "r0"; // stage 0's CURRENT is the diffuse colour
  case Arg::Diffuse: return "v0";
  case Arg::Specular: return "v1";
  case Arg::Texture: return fmt::format("t{}", n);
  case Arg::TFactor: return "c0";
  }
  return "r0";
}

std::string instruction(const Operation& o, uint32_t n, std::string_view mask) {
  const std::string d = fmt::format("r0{}", mask);
  auto a = [&](size_t i) { return reg(o.args.at(i), n); };
  switch (o.op) {
  case Op::Disable: return mask == ".a" ? fmt::format("mov {}, {}", d, reg(Arg::Current, n)) : "";
  case Op::SelectArg1: return fmt::format("mov {}, {}", d, a(0));
  case Op::SelectArg2: return fmt::format("mov {}, {}", d, a(1));
  case Op::Modulate: return fmt::format("mul {}, {}, {}", d, a(0), a(1));
  case Op::Modulate2x: return fmt::format("mul_x2 {}, {}, {}", d, a(0), a(1));
  case Op::Modulate4x: return fmt::format("mul_x4 {}, {}, {}", d, a(0), a(1));
  case Op::Add: return fmt::format("add {}, {}, {}", d, a(0), a(1));
  case Op::AddSigned: return fmt::format("add_sat {}, {}, {}_bias", d, a(0), a(1));
  case Op::Subtract: return fmt::format("sub_sat {}, {}, {}", d, a(0), a(1));
  case Op::ModulateAlphaAddColor: return fmt::format("mad {}, {}, {}.a, {}", d, a(1), a(0), a(0));
  }
  return "";
}

std::string op_comment(const Operation& o, uint32_t n, std::string_view state) {
  return fmt::format("  // stage {} {} (line {})", n, state, o.loc.line);
}

ir::Result<std::shared_ptr<const ir::Program>> read(std::string text, std::string name) {
  ir::SourceManager sources;
  const uint32_t file = sources.add(name, std::move(text));
  assembly::LoadOptions options;
  options.parse.allow_include = false;
  options.warnings = false;
  assembly::Loaded r = assembly::load_listing(file, sources, options);
  if (!r.program)
    return ir::fail(std::move(name), "listing", ir::render_text(r.program.diagnostics(), sources));
  return std::make_shared<const ir::Program>(std::move(r.program).value());
}

} // namespace

ir::Result<Lowered> lower_stage_states(const StageStates& st) {
  Lowered out;
  uint32_t enabled = 0;
  while (enabled < kD3DMaxStages && stage_enabled(st, enabled)) ++enabled;
  bool diffuse = false, specular = false, tfactor = false;
  std::vector<bool> texture(enabled, false);
  std::string code;
  for (uint32_t n = 0; n < std::max(enabled, 1u); ++n) {
    const Stage none;
    const Stage& s = n < st.stages.size() ? st.stages[n] : none;
    const Operation c = color_of(s, n), a = alpha_of(s, n);
    for (const Operation* o : {&c, &a}) {
      std::optional<Operation> opt = *o;
      if (n < enabled && reads(opt, Arg::Texture)) texture[n] = true;
      diffuse = diffuse || reads(opt, Arg::Diffuse) || (n == 0 && reads(opt, Arg::Current));
      specular = specular || reads(opt, Arg::Specular);
      tfactor = tfactor || reads(opt, Arg::TFactor);
    }
    if (n >= enabled) { // stage 0 disabled: the diffuse colour is the result
      code += "mov r0, v0  // stage 0 colorop disable: the diffuse colour\n";
      diffuse = true;
      break;
    }
    code += instruction(c, n, ".rgb") + op_comment(c, n, "colorop") + "\n";
    if (a.op == Op::Disable) {
      if (n == 0) code += "mov r0.a, v0  // stage 0 alphaop disable: the diffuse alpha\n";
      diffuse = diffuse || n == 0;
    } else {
      code += instruction(a, n, ".a") +
              (s.alpha ? op_comment(a, n, "alphaop")
                       : fmt::format("  // stage {} alphaop default", n)) +
              "\n";
    }
  }

  std::string ps = "ps.1.1\n// lowered from texture-stage states (docs/stage-states.md)\n";
  if (tfactor) {
    const uint32_t f = st.tfactor;
    ps += fmt::format("def c0, {:.9g}, {:.9g}, {:.9g}, {:.9g}  // tfactor 0x{:08x}\n",
                      d3dcolor_channel(uint8_t(f >> 16)), d3dcolor_channel(uint8_t(f >> 8)),
                      d3dcolor_channel(uint8_t(f)), d3dcolor_channel(uint8_t(f >> 24)), f);
  }
  for (uint32_t n = 0; n < texture.size(); ++n)
    if (texture[n]) ps += fmt::format("tex t{}\n", n), out.texture_stages = n + 1;
  ps += code;

  std::string vs = "vs.1.1\n// lowered from texture-stage states (docs/stage-states.md)\n"
                   "dcl_position v0\ndcl_texcoord v3\nmov oPos, v0\n";
  for (uint32_t n = 0; n < texture.size(); ++n)
    if (texture[n]) vs += fmt::format("add oT{}, v3, c{}  // stage {}: uv + offset\n", n, n, n);
  if (diffuse) vs += fmt::format("mov oD0, c{}  // the diffuse D3DCOLOR\n", kDiffuseConstant);
  if (specular) vs += fmt::format("mov oD1, c{}  // the specular D3DCOLOR\n", kSpecularConstant);

  ir::Result<std::shared_ptr<const ir::Program>> vs_program = read(vs, "<lowered tss vertex>");
  if (!vs_program) return std::move(vs_program).failure();
  out.vs = std::move(vs_program).value();
  ir::Result<std::shared_ptr<const ir::Program>> ps_program = read(ps, "<lowered tss pixel>");
  if (!ps_program) return std::move(ps_program).failure();
  out.ps = std::move(ps_program).value();
  out.vs_text = std::move(vs);
  out.ps_text = std::move(ps);
  return out;
}

ir::Result<Lowered> load_stage_states(std::string text, std::string name, uint32_t max_stages) {
  ir::SourceManager sources;
  ir::DiagnosticSink diags;
  const uint32_t file = sources.add(name, std::move(text));
  std::optional<StageStates> st = parse_stage_states(file, sources, diags, max_stages);
  if (!st) return ir::fail(std::move(name), "tss", ir::render_text(diags, sources));
  return lower_stage_states(*st);
}

} // namespace tierlift::effects::tss
