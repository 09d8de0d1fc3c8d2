// The entry point: calls the D3D program, then copies output registers to the stage
// interface (docs/spirv-mapping.md): the position fix-up (y flip, D3D9 half-pixel shift as
// specialization constants), oD#/oFog saturation, fragment colours and depth. Then the
// module is finished, validated and (optionally) optimised.
#include <spirv/unified1/GLSL.std.450.h>

#include "tierlift/codegen/emitter.h"
#include "tierlift/ir/sm3_interface.h"

namespace tierlift::codegen {

using ir::RegFile;
using spv::Op;
using SC = spv::StorageClass;

Id Emitter::output_var(const InterfaceVar& iv, Id type) {
  const Id var = b.global_variable(b.type_pointer(SC::Output, type), SC::Output);
  if (iv.kind == InterfaceKind::BuiltIn) {
    const spv::BuiltIn bi = iv.builtin == "Position"    ? spv::BuiltIn::Position
                            : iv.builtin == "PointSize" ? spv::BuiltIn::PointSize
                                                        : spv::BuiltIn::FragDepth;
    b.decorate(var, spv::Decoration::BuiltIn, static_cast<uint32_t>(bi));
  } else {
    b.decorate(var, spv::Decoration::Location, iv.location);
  }
  b.name(var, "out_" + iv.name);
  interface_.push_back(iv);
  interface_ids_.push_back(var);
  return var;
}

namespace {
InterfaceVar make_iv(InterfaceKind kind, RegFile file, uint32_t index, uint32_t location,
                     uint32_t components, std::string builtin = {}) {
  InterfaceVar iv;
  iv.kind = kind;
  iv.file = file;
  iv.index = index;
  iv.location = location;
  iv.components = components;
  iv.builtin = std::move(builtin);
  iv.name = ir::register_name(file, index);
  if (file == RegFile::TexCrdOut || file == RegFile::AttrOut) {
    iv.usage = file == RegFile::TexCrdOut ? ir::DeclUsage::TexCoord : ir::DeclUsage::Color;
    iv.usage_index = static_cast<uint8_t>(index);
  }
  return iv;
}
} // namespace

void Emitter::emit_entry() {
  const Id fn = b.fresh_id();
  b.begin_function(t_void, b.type_function(t_void), fn);
  b.name(fn, opt.entry_point);
  b.begin_block(b.fresh_id());
  if (tracing()) trace_begin_entry();
  b.op(Op::OpFunctionCall, t_void, {fn_main_});
  const bool vertex = prog.stage() == ir::ShaderStage::Vertex;
  auto load = [&](RegFile file, uint32_t index) {
    return b.op(Op::OpLoad, t_vec4, {register_var(file, index)});
  };
  if (vertex) {
    std::set<std::pair<RegFile, uint32_t>> outs;
    if (plan.vs_outputs) {
      outs = *plan.vs_outputs;
    } else {
      for (const auto& [key, var] : regs_)
        if (key.first == RegFile::RastOut || key.first == RegFile::AttrOut ||
            key.first == RegFile::TexCrdOut)
          outs.insert(key);
    }
    outs.insert({RegFile::RastOut, ir::kRastPos});
    for (const auto& [file, index] : outs) {
      const Id v = load(file, index);
      if (file == RegFile::RastOut && index == ir::kRastPos) {
        const Id flip = spec_float(kSpecFlipY, opt.flip_y ? -1.0f : 1.0f, "flip_y");
        const Id offx = spec_float(kSpecPixelOffsetX, opt.pixel_offset_x, "pixel_offset_x");
        const Id offy = spec_float(kSpecPixelOffsetY, opt.pixel_offset_y, "pixel_offset_y");
        const Id w = comp(v, 3);
        const Id x = fadd(comp(v, 0), fmul(offx, w, 1), 1);
        const Id y = fadd(fmul(flip, comp(v, 1), 1), fmul(offy, w, 1), 1);
        const Id pos = compose(x, y, comp(v, 2), w);
        const Id var =
            output_var(make_iv(InterfaceKind::BuiltIn, file, index, 0, 4, "Position"), t_vec4);
        b.op_void(Op::OpStore, {var, pos});
      } else if (file == RegFile::RastOut) {
        const bool fog = index == ir::kRastFog;
        Id x = comp(v, 0);
        if (fog) x = rule::saturate(arith(1), x);
        const Id var =
            output_var(fog ? make_iv(InterfaceKind::Output, file, index, kFogLocation, 1)
                           : make_iv(InterfaceKind::BuiltIn, file, index, 0, 1, "PointSize"),
                       t_float);
        b.op_void(Op::OpStore, {var, x});
      } else {
        // oD# reach the pixel stage saturated (docs/d3d9-rules.md §3.1) unless a vs_3_0 feeds
        // a ps_3_0, whose colours are general outputs and float inputs (NUMERICS.md F6).
        const bool color = file == RegFile::AttrOut;
        const Id value = color && plan.saturate_color_outputs ? rule::saturate(arith(4), v) : v;
        const Id var =
            output_var(make_iv(InterfaceKind::Output, file, index,
                               color ? kColorLocation + index : kTexCoordLocation + index, 4),
                       t_vec4);
        b.op_void(Op::OpStore, {var, value});
      }
    }
  } else {
    if (ir::is_ps1x(prog.profile)) {
      const Id var = output_var(make_iv(InterfaceKind::Output, RegFile::Temp, 0, 0, 4), t_vec4);
      const Id r0 = load(RegFile::Temp, 0);
      b.op_void(Op::OpStore, {var, opt.srgb_write[0] ? srgb_encode(r0) : r0});
    } else {
      std::vector<uint32_t> colors;
      for (const auto& [key, var] : regs_)
        if (key.first == RegFile::ColorOut) colors.push_back(key.second);
      // A ps_3_0 may write no oC# (only oDepth, or nothing: a validator warning). D3D9 leaves
      // the colour undefined; a Vulkan fragment shader without the output leaves the
      // attachment's value undefined too, and lavapipe stores what its registers held. oC0 is
      // stored from its register all the same, which starts at 0 as every register does
      // (and as the interpreter's outputs do), so both devices draw (0, 0, 0, 0).
      if (colors.empty()) colors.push_back(0);
      for (uint32_t n : colors) {
        const Id var =
            output_var(make_iv(InterfaceKind::Output, RegFile::ColorOut, n, n, 4), t_vec4);
        const Id color = load(RegFile::ColorOut, n);
        const bool srgb = n < opt.srgb_write.size() && opt.srgb_write[n];
        b.op_void(Op::OpStore, {var, srgb ? srgb_encode(color) : color});
      }
    }
    if (writes_depth_) {
      const Id var = output_var(
          make_iv(InterfaceKind::BuiltIn, RegFile::DepthOut, 0, 0, 1, "FragDepth"), t_float);
      // Clamped to the viewport's depth range [0, 1] by rule 23's selects (NaN → 0), as the
      // CPU device does (pass/depth.h): Vulkan leaves FragDepth outside [0, 1] undefined for
      // a float depth buffer without depth clamping, so lavapipe never sees such a value.
      const Id depth = rule::saturate(arith(1), comp(load(RegFile::DepthOut, 0), 0));
      b.op_void(Op::OpStore, {var, depth});
    }
  }
  b.op_void(Op::OpReturn, {});
  b.end_function();
  b.entry_point(vertex ? spv::ExecutionModel::Vertex : spv::ExecutionModel::Fragment, fn,
                opt.entry_point, interface_ids_);
  if (!vertex) {
    b.execution_mode(fn, spv::ExecutionMode::OriginUpperLeft);
    if (writes_depth_) b.execution_mode(fn, spv::ExecutionMode::DepthReplacing);
  }
}

std::optional<ShaderModule> Emitter::run() {
  begin_module();
  emit_code();
  if (failed) return std::nullopt;
  emit_entry();
  declare_uniforms();
  if (tracing()) declare_trace_buffer();
  if (uses_kill_ && opt.kill == KillMode::Demote) {
    b.capability(spv::Capability::DemoteToHelperInvocation);
    b.extension("SPV_EXT_demote_to_helper_invocation");
  }
  ShaderModule m;
  m.stage = prog.stage();
  m.words = b.finish();
  const ir::SourceLoc where = prog.version_loc;
  if (ir::Status valid = validate(m.words); !valid) {
    diags.error(where, "spirv-val",
                "internal error: the generated SPIR-V fails validation: " + valid.message());
    return std::nullopt;
  }
  if (opt.optimize) {
    std::vector<uint32_t> optimised = m.words;
    ir::Status done = optimize(optimised);
    if (done) done = validate(optimised);
    if (!done) {
      diags.error(where, "spirv-opt", "internal error: optimisation failed: " + done.message());
      return std::nullopt;
    }
    m.words = std::move(optimised);
  }
  m.entry_point = opt.entry_point;
  m.interface = interface_;
  if (uniform_var_) {
    m.uniforms = layout_;
    m.uniforms.binding =
        prog.stage() == ir::ShaderStage::Vertex ? kVertexConstantsBinding : kPixelConstantsBinding;
    m.uniforms.float_used.assign(consts_read_.begin(), consts_read_.end());
  }
  for (const auto& [stage, var] : samplers_)
    m.samplers.push_back(
        {kDescriptorSet, sampler_binding(stage), stage, sampler_type(stage), fetches(stage)});
  m.spec_constants = spec_info_;
  m.block_defs.assign(block_defs_.begin(), block_defs_.end());
  m.writes_depth = writes_depth_;
  m.uses_kill = uses_kill_;
  if (tracing())
    m.trace = TraceInfo{kDescriptorSet, opt.trace->binding, static_cast<uint32_t>(prog.code.size()),
                        trace_points_};
  return m;
}

} // namespace tierlift::codegen
