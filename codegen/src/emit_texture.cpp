// Texture instructions (docs/d3d9-rules.md §5.5–§5.7): sampling through combined image samplers
// at set 0, binding 2 + stage (a vertex program's: 19 + stage); ps_1_1…1_3 texture-address
// instructions with their pad rows; texkill as OpKill or OpDemoteToHelperInvocation.
#include <array>

#include <fmt/format.h>

#include <spirv/unified1/GLSL.std.450.h>

#include "tierlift/codegen/emitter.h"

namespace tierlift::codegen {

using ir::Opcode;
using ir::RegFile;
using spv::Op;
using SC = spv::StorageClass;

ir::SamplerType Emitter::sampler_type(uint32_t stage) const {
  if (ir::is_sm2_or_later(prog.profile)) { // ps_2_0, ps_2_x, ps_3_0 declare their samplers
    for (const ir::Declaration& d : prog.decls)
      if (d.reg.file == RegFile::Sampler && d.reg.index == stage &&
          d.sampler_type != ir::SamplerType::Unknown)
        return d.sampler_type;
    return ir::SamplerType::Tex2D;
  }
  const ir::SamplerType t = opt.stage_texture_type[stage & 15];
  return t == ir::SamplerType::Unknown ? ir::SamplerType::Tex2D : t;
}

namespace {
spv::Dim dim_of(ir::SamplerType t) {
  switch (t) {
  case ir::SamplerType::Cube: return spv::Dim::Cube;
  case ir::SamplerType::Volume: return spv::Dim::Dim3D;
  default: return spv::Dim::Dim2D;
  }
}
} // namespace

Id Emitter::sampler_var(uint32_t stage) {
  if (auto it = samplers_.find(stage); it != samplers_.end()) return it->second;
  const Id image = b.type_image(t_float, dim_of(sampler_type(stage)));
  const Id sampled = b.type_sampled_image(image);
  const Id var =
      b.global_variable(b.type_pointer(SC::UniformConstant, sampled), SC::UniformConstant);
  b.decorate(var, spv::Decoration::DescriptorSet, kDescriptorSet);
  b.decorate(var, spv::Decoration::Binding, sampler_binding(stage));
  b.name(var, fmt::format("s{}", stage)); // not "s" + temporary: GCC 12 -Wrestrict at -O3
  samplers_.emplace(stage, var);
  return var;
}

// The CodegenOptions stage_* arrays describe the pixel stage's samplers: a vertex program's
// s# (vs_3_0 texldl) are other samplers, read with none of those options.
bool Emitter::fetches(uint32_t stage) const {
  return prog.stage() == ir::ShaderStage::Pixel && opt.stage_fetch_unorm8[stage & 15] &&
         sampler_type(stage) == ir::SamplerType::Tex2D;
}

uint32_t Emitter::sampler_binding(uint32_t stage) const {
  return (prog.stage() == ir::ShaderStage::Vertex ? kFirstVertexSamplerBinding
                                                  : kFirstSamplerBinding) +
         stage;
}

Id Emitter::clamp_uv01(Id uv) {
  const Id zero2 = b.const_composite(t_vec2, std::array{f(0), f(0)});
  const Id one2 = b.const_composite(t_vec2, std::array{f(1), f(1)});
  return b.ext_inst(glsl, t_vec2, GLSLstd450NClamp, std::array{uv, zero2, one2});
}

Id Emitter::point_texel_unorm8(Id si, Id uv) {
  if (opt.point_sampling_floors) {
    // The device's own point sampler picks the interpreter's texel for u in [0, 1]; outside,
    // the edge texel is the one u = 0 or 1 picks, and NClamp sends a NaN to 0 as point_texel
    // does (NMax returns the other operand).
    return b.op(Op::OpImageSampleImplicitLod, t_vec4, {si, clamp_uv01(uv)});
  }
  const Id zero2 = b.const_composite(t_vec2, std::array{f(0), f(0)});
  const Id one2 = b.const_composite(t_vec2, std::array{f(1), f(1)});
  // The texel index point sampling takes on each axis: floor(fl32(u·N)) (one float multiply,
  // as the interpreter's point_texel), NaN → 0, clamped to [0, N − 1] (CLAMP addressing).
  b.capability(spv::Capability::ImageQuery);
  const Id t_ivec2 = b.type_vector(t_int, 2), t_bvec2 = b.type_vector(t_bool, 2);
  const Id image = b.op(Op::OpImage, b.type_image(t_float, spv::Dim::Dim2D), {si});
  const Id size = b.op(Op::OpImageQuerySizeLod, t_ivec2, {image, b.const_int(0)});
  const Id n = b.op(Op::OpConvertSToF, t_vec2, {size});
  const Id x = b.op(Op::OpFMul, t_vec2, {uv, n});
  b.decorate(x, spv::Decoration::NoContraction);
  const Id finite = b.op(Op::OpSelect, t_vec2, {b.op(Op::OpIsNan, t_bvec2, {x}), zero2, x});
  const Id floor = b.ext_inst(glsl, t_vec2, GLSLstd450Floor, std::array{finite});
  const Id last = b.op(Op::OpFSub, t_vec2, {n, one2});
  const Id clamped = b.ext_inst(glsl, t_vec2, GLSLstd450FClamp, std::array{floor, zero2, last});
  const Id index = b.op(Op::OpConvertFToS, t_ivec2, {clamped});
  return b.op(Op::OpImageFetch, t_vec4,
              {image, index, static_cast<uint32_t>(spv::ImageOperandsMask::Lod), b.const_int(0)});
}

Id Emitter::fetch_unorm8(Id si, Id uv) {
  const Id v = point_texel_unorm8(si, uv);
  // The texel's exact k/255.0f from the device's UNORM value v (unorm8_decode.h says why each
  // decode is exact where the device chose it; decode_on_host is the same arithmetic).
  switch (opt.unorm8_decode) {
  case Unorm8Decode::None: return v;
  case Unorm8Decode::TwoMultiply:
    return fmul(fmul(v, splat(f(kTwoMultiply[0]))), splat(f(kTwoMultiply[1])));
  case Unorm8Decode::RoundAndRebuild: break;
  }
  //   k = roundEven(v·255)                      exact: v is far closer to k/255 than 1/510
  //   k/255 = (k·65793 + k/255) · 2^-24         since 2^24/255 = 65793 + 1/255
  //   fl32(k/255) = fl32(k·65793 + v) · 2^-24   k·65793 < 2^24 is exact; v's error is far
  //                                             below the distance of k·65793 + k/255 from a
  //                                             rounding boundary (k/255 is a repeating
  //                                             8-bit pattern), and 2^-24 scales exactly.
  // Every step is one float operation (tests check all 256 levels, ±2 ulps of v).
  const Id k = b.ext_inst(glsl, t_vec4, GLSLstd450RoundEven, std::array{fmul(v, splat(f(255.0f)))});
  const Id sum = fadd(fmul(k, splat(f(65793.0f))), v);
  return fmul(sum, splat(f(0x1p-24f)));
}

Id Emitter::sample(uint32_t stage, Id coord, std::optional<Id> bias, std::optional<Id> lod,
                   std::optional<std::pair<Id, Id>> grad) {
  const Id var = sampler_var(stage);
  const ir::SamplerType type = sampler_type(stage);
  const Id image = b.type_image(t_float, dim_of(type));
  const Id si = b.op(Op::OpLoad, b.type_sampled_image(image), {var});
  auto coords = [&](Id v) {
    return type == ir::SamplerType::Tex2D ? b.op(Op::OpVectorShuffle, t_vec2, {v, v, 0, 1})
                                          : b.op(Op::OpVectorShuffle, t_vec3, {v, v, 0, 1, 2});
  };
  Id c = coords(coord);
  // A bias changes nothing there: one mip level, POINT both ways.
  if (fetches(stage)) return fetch_unorm8(si, c);
  // A POINT/CLAMP read at the clamped coordinate: the same texel, and no u·N that
  // overflows the device's conversion to an index (CodegenOptions::stage_point_clamped).
  const bool point_clamped = prog.stage() == ir::ShaderStage::Pixel
                                 ? opt.stage_point_clamped[stage & 15]
                                 : opt.vertex_point_clamped[stage & 3];
  if (type == ir::SamplerType::Tex2D && point_clamped) c = clamp_uv01(c);
  if (grad) // one level, minLod = maxLod = 0: level 0 whatever the gradients (rule F10)
    return b.op(Op::OpImageSampleExplicitLod, t_vec4,
                {si, c, static_cast<uint32_t>(spv::ImageOperandsMask::Grad), coords(grad->first),
                 coords(grad->second)});
  if (lod)
    return b.op(Op::OpImageSampleExplicitLod, t_vec4,
                {si, c, static_cast<uint32_t>(spv::ImageOperandsMask::Lod), *lod});
  if (bias)
    return b.op(Op::OpImageSampleImplicitLod, t_vec4,
                {si, c, static_cast<uint32_t>(spv::ImageOperandsMask::Bias), *bias});
  return b.op(Op::OpImageSampleImplicitLod, t_vec4, {si, c});
}

Id Emitter::texcoord_input(uint32_t m) {
  return b.op(Op::OpLoad, t_vec4, {input_var(RegFile::Texture, m)});
}

void Emitter::kill_if_any_negative(Id value, int components) {
  uses_kill_ = true;
  Id any = 0;
  for (int i = 0; i < components; ++i) {
    const Id lt = cmp(Op::OpFOrdLessThan, comp(value, static_cast<uint32_t>(i)), f(0.0f), 1);
    any = any ? b.op(Op::OpLogicalOr, t_bool, {any, lt}) : lt;
  }
  if (!any) return;
  const Id kill = b.fresh_id(), merge = b.fresh_id();
  b.op_void(Op::OpSelectionMerge,
            {merge, static_cast<uint32_t>(spv::SelectionControlMask::MaskNone)});
  b.op_void(Op::OpBranchConditional, {any, kill, merge});
  b.begin_block(kill);
  if (opt.kill == KillMode::Demote) {
    b.op_void(Op::OpDemoteToHelperInvocation, {});
    b.op_void(Op::OpBranch, {merge});
  } else {
    b.op_void(Op::OpKill, {});
  }
  b.begin_block(merge);
}

PendingStore Emitter::texture_store(const ir::Instruction& ins, Id v) {
  PendingStore st;
  st.dst = *ins.dst;
  st.mods = ins.mods;
  st.mask = ins.dst->mask;
  st.value = v;
  return st;
}

PendingStore Emitter::depth_store(Id z) {
  PendingStore st;
  st.dst.file = RegFile::DepthOut;
  st.dst.index = 0;
  st.mask = 0x1;
  st.value = splat(z);
  return st;
}

Id Emitter::stage_texcoord(uint32_t stage) {
  Id c = texcoord_input(stage);
  if (opt.stage_projected[stage & 15] && sampler_type(stage) != ir::SamplerType::Cube) {
    // (x/w, y/w, z/w, 1), as the interpreter's projected().
    const Id w = comp(c, 3);
    c = compose(fdiv(comp(c, 0), w, 1), fdiv(comp(c, 1), w, 1), fdiv(comp(c, 2), w, 1), f(1.0f));
  }
  return c;
}

bool Emitter::emit_texture(const ir::Instruction& ins, std::optional<PendingStore>& out) {
  const ir::OpInfo& info = ir::op_info(ins.op);
  if (!ins.dst || ins.src.size() < info.num_src) {
    error(ins.loc, "malformed instruction '" + std::string(info.mnemonic) + "'");
    return false;
  }
  const uint32_t m = ins.dst->index;
  const Id zero = f(0.0f);
  auto result = [&](Id v) {
    out = texture_store(ins, v);
    return true;
  };
  switch (ins.op) {
  case Opcode::Tex: return result(sample(m, stage_texcoord(m)));
  case Opcode::TexLd14: return result(sample(m, load_src(ins.src[0])));
  case Opcode::TexLd:
  case Opcode::TexLdP:
  case Opcode::TexLdB:
  case Opcode::TexLdD:
  case Opcode::TexLdL: {
    const uint32_t s = ins.src[1].index;
    Id c = load_src(ins.src[0]);
    if (ins.op == Opcode::TexLdD)
      return result(sample(s, c, std::nullopt, std::nullopt,
                           std::pair{load_src(ins.src[2]), load_src(ins.src[3])}));
    if (ins.op == Opcode::TexLdP) return result(sample(s, fdiv(c, splat(comp(c, 3)))));
    if (ins.op == Opcode::TexLdB) return result(sample(s, c, comp(c, 3)));
    if (ins.op == Opcode::TexLdL) return result(sample(s, c, std::nullopt, comp(c, 3)));
    return result(sample(s, c));
  }
  case Opcode::TexCoord: {
    const Id c = rule::saturate(arith(4), texcoord_input(m));
    return result(compose(comp(c, 0), comp(c, 1), comp(c, 2), f(1.0f)));
  }
  case Opcode::TexCrd: return result(load_src(ins.src[0]));
  case Opcode::TexKill: {
    Id v;
    int n = 3;
    if (ir::is_ps11_13(prog.profile)) {
      v = texcoord_input(m);
    } else {
      v = load_register(ins.dst->file, m, std::nullopt);
      // SM2 tests all four components (Wine; the docs say three, docs/d3d9-rules.md §5.7).
      if (!ir::is_ps1x(prog.profile)) n = 4;
    }
    // A predicated texkill tests component i only where p0's component i holds (rule F3):
    // the others are tested as 0, which kills nothing.
    if (ins.pred) v = b.op(Op::OpSelect, t_vec4, {predicate_mask(*ins.pred), v, splat(f(0.0f))});
    kill_if_any_negative(v, n);
    return true;
  }
  case Opcode::TexBem:
  case Opcode::TexBemL: return result(bump_sample(ins));
  case Opcode::TexReg2Ar:
  case Opcode::TexReg2Gb:
  case Opcode::TexReg2Rgb: {
    const Id tn = load_src(ins.src[0]);
    const Id c = ins.op == Opcode::TexReg2Ar ? compose(comp(tn, 3), comp(tn, 0), zero, zero)
                 : ins.op == Opcode::TexReg2Gb
                     ? compose(comp(tn, 1), comp(tn, 2), zero, zero)
                     : compose(comp(tn, 0), comp(tn, 1), comp(tn, 2), zero);
    return result(sample(m, c));
  }
  case Opcode::TexDp3: return result(splat(dot3_texcoord(ins, m)));
  case Opcode::TexDp3Tex:
    return result(sample(m, compose(dot3_texcoord(ins, m), zero, zero, zero)));
  case Opcode::TexDepth: {
    const Id r5 = load_register(RegFile::Temp, m, std::nullopt);
    const Id r = comp(r5, 0), g = comp(r5, 1);
    out = depth_store(rule::depth_ratio(arith(1), r, g));
    return true;
  }
  default: return emit_texture_matrix(ins, out);
  }
}

Id Emitter::dot3_texcoord(const ir::Instruction& ins, uint32_t stage) {
  return dot(texcoord_input(stage), load_src(ins.src[0]), 3);
}

// texbem / texbeml: the coordinate offset by the bump matrix times the source's (r, g), and
// for texbeml the sample scaled by the luminance.
Id Emitter::bump_sample(const ir::Instruction& ins) {
  const uint32_t m = ins.dst->index;
  const Id tn = load_src(ins.src[0]);
  const Id c = stage_texcoord(m);
  const Id mat = bumpenv(m, 0);
  const Id r = comp(tn, 0), g = comp(tn, 1);
  const Id u = rule::bump_offset(arith(1), comp(c, 0), comp(mat, 0), r, comp(mat, 2), g);
  const Id v = rule::bump_offset(arith(1), comp(c, 1), comp(mat, 1), r, comp(mat, 3), g);
  Id s = sample(m, compose(u, v, comp(c, 2), comp(c, 3)));
  if (ins.op == Opcode::TexBemL) {
    const Id lum = bumpenv(m, 1);
    const Id k = rule::bump_luminance(arith(1), comp(tn, 2), comp(lum, 0), comp(lum, 1));
    s = rule::mul(arith(4), s, splat(k));
  }
  return s;
}

// The texm3x2 / texm3x3 family: pad rows keep their dot products, the last row uses them.
bool Emitter::emit_texture_matrix(const ir::Instruction& ins, std::optional<PendingStore>& out) {
  const uint32_t m = ins.dst->index;
  const Id zero = f(0.0f);
  switch (ins.op) {
  case Opcode::TexM3x2Pad:
  case Opcode::TexM3x3Pad:
    pad_value_[pad_count_ & 1] = dot3_texcoord(ins, m);
    ++pad_count_;
    return true;
  case Opcode::TexM3x2Tex:
  case Opcode::TexM3x2Depth: {
    const Id v = dot3_texcoord(ins, m);
    const Id u = pad_value_[0] ? pad_value_[0] : zero;
    pad_count_ = 0;
    out = ins.op == Opcode::TexM3x2Tex ? texture_store(ins, sample(m, compose(u, v, zero, zero)))
                                       : depth_store(rule::depth_ratio(arith(1), u, v));
    return true;
  }
  case Opcode::TexM3x3Tex:
  case Opcode::TexM3x3:
  case Opcode::TexM3x3Spec:
  case Opcode::TexM3x3VSpec: {
    const Id w = dot3_texcoord(ins, m);
    const Id u = pad_value_[0] ? pad_value_[0] : zero;
    const Id v = pad_value_[1] ? pad_value_[1] : zero;
    pad_count_ = 0;
    const Id n = compose(u, v, w, zero);
    if (ins.op == Opcode::TexM3x3) {
      out = texture_store(ins, compose(u, v, w, f(1.0f)));
    } else if (ins.op == Opcode::TexM3x3Tex) {
      out = texture_store(ins, sample(m, n));
    } else {
      Id e;
      if (ins.op == Opcode::TexM3x3Spec) {
        e = load_src(ins.src[1]);
      } else {
        const uint32_t m0 = m >= 2 ? m - 2 : 0, m1 = m >= 1 ? m - 1 : 0;
        e = compose(comp(texcoord_input(m0), 3), comp(texcoord_input(m1), 3),
                    comp(texcoord_input(m), 3), zero);
      }
      const Id k = rule::reflect_scale(arith(1), dot(n, e, 3), dot(n, n, 3));
      const Id r = rule::reflect_component(arith(4), splat(k), n, e);
      out = texture_store(ins, sample(m, r));
    }
    return true;
  }
  default:
    error(ins.loc, "code generation for '" + std::string(ir::op_info(ins.op).mnemonic) +
                       "' is not implemented");
    return false;
  }
}

} // namespace tierlift::codegen
