// Module skeleton: capabilities, types, the D3D program as one function over Private
// register variables, the entry point that calls it and copies the output registers to the
// stage interface, and the uniform block sized once every constant read is known.
#include <spirv/unified1/GLSL.std.450.h>
#include <tuple>

#include "tierlift/codegen/emitter.h"
#include "tierlift/ir/profile.h"

namespace tierlift::codegen {

using ir::RegFile;
using spv::Op;
using SC = spv::StorageClass;

Emitter::Emitter(const ir::Program& program, const CodegenOptions& options,
                 const EmitPlan& emit_plan, ir::DiagnosticSink& sink)
    : prog(program), opt(options), plan(emit_plan), diags(sink), defs_(ir::fold_defs(program)) {}

void Emitter::error(const ir::SourceLoc& loc, const std::string& message) {
  diags.error(loc, "codegen", message);
  failed = true;
}

void Emitter::begin_module() {
  b.capability(spv::Capability::Shader);
  glsl = b.ext_inst_import("GLSL.std.450");
  b.memory_model(spv::AddressingModel::Logical, spv::MemoryModel::GLSL450);
  t_void = b.type_void();
  t_bool = b.type_bool();
  t_bvec4 = b.type_vector(t_bool, 4);
  t_float = b.type_float();
  t_vec2 = b.type_vector(t_float, 2);
  t_vec3 = b.type_vector(t_float, 3);
  t_vec4 = b.type_vector(t_float, 4);
  t_int = b.type_int(true);
  t_ivec4 = b.type_vector(t_int, 4);
  t_uint = b.type_int(false);
  uniform_var_ = b.fresh_id();
  if (ir::is_ps1x(prog.profile)) {
    spec_max_value_ =
        spec_float(kSpecPs1xMaxValue, opt.conventions.ps1x_max_value, "ps1x_max_value");
  }
}

Id Emitter::spec_float(uint32_t spec_id, float default_value, const std::string& name) {
  const Id id = b.spec_const_float(default_value);
  b.decorate(id, spv::Decoration::SpecId, spec_id);
  b.name(id, name);
  spec_info_.push_back({spec_id, default_value, name});
  return id;
}

Id Emitter::register_var(RegFile file, uint32_t index) {
  const auto key = std::make_pair(file, index);
  if (auto it = regs_.find(key); it != regs_.end()) return it->second;
  const bool addr = file == RegFile::Addr;
  const Id type = addr ? t_ivec4 : t_vec4;
  const Id var =
      b.global_variable(b.type_pointer(SC::Private, type), SC::Private, b.const_null(type));
  b.name(var, file == RegFile::Addr ? std::string("a0") : ir::register_name(file, index));
  regs_.emplace(key, var);
  return var;
}

Id Emitter::input_var(RegFile file, uint32_t index) {
  const auto key = std::make_pair(file, index);
  if (auto it = inputs_.find(key); it != inputs_.end()) return it->second;
  const bool vertex = prog.stage() == ir::ShaderStage::Vertex;
  const Id var = b.global_variable(b.type_pointer(SC::Input, t_vec4), SC::Input);
  InterfaceVar iv;
  iv.kind = InterfaceKind::Input;
  iv.file = file;
  iv.index = index;
  iv.location =
      vertex ? index
             : (file == RegFile::Texture ? kTexCoordLocation + index : kColorLocation + index);
  iv.name = ir::register_name(file, index);
  if (vertex) {
    for (const ir::Declaration& d : prog.decls)
      if (d.reg.file == RegFile::Input && d.reg.index == index) {
        iv.usage = d.usage;
        iv.usage_index = d.usage_index;
      }
  } else {
    iv.usage = file == RegFile::Texture ? ir::DeclUsage::TexCoord : ir::DeclUsage::Color;
    iv.usage_index = static_cast<uint8_t>(index);
    // ps_2_0 dcl_centroid: interpolate inside the primitive (docs/d3d9-rules.md §9.4).
    for (const ir::Declaration& d : prog.decls)
      if (d.reg.file == file && d.reg.index == index && d.mods.centroid)
        b.decorate(var, spv::Decoration::Centroid);
  }
  b.decorate(var, spv::Decoration::Location, iv.location);
  b.name(var, "in_" + iv.name);
  interface_.push_back(iv);
  interface_ids_.push_back(var);
  inputs_.emplace(key, var);
  return var;
}

void Emitter::declare_uniforms() {
  const bool has_int =
      prog.profile == ir::Profile::vs_2_0 || ir::has_predication(prog.profile); // i#, b#
  const bool has_bump = ir::is_ps1x(prog.profile);
  if (const_relative_) {
    float_count_ = relative_limit();
  } else {
    float_count_ = consts_read_.empty() ? 0 : *consts_read_.rbegin() + 1;
  }
  // A block with no member in use is still declared when flow control or bump mapping
  // reads it; otherwise the module has no uniform block at all.
  const bool needs = float_count_ > 0 || has_int || has_bump;
  if (!needs) {
    uniform_var_ = 0;
    return;
  }
  const uint32_t fcount = float_count_ > 0 ? float_count_ : 1;
  layout_ = uniform_block_layout(fcount, has_int, has_bump);
  layout_.float_count = float_count_;
  // Array types are shared (c[16] and bumpenv[16] are one type): decorate each once.
  std::set<Id> strided;
  auto array = [&](Id elem, uint32_t count) {
    const Id arr = b.type_array(elem, b.const_uint(count));
    if (strided.insert(arr).second)
      b.decorate(arr, spv::Decoration::ArrayStride, UniformBlockInfo::kStride);
    return arr;
  };
  using Member = std::tuple<Id, const char*, uint32_t>; // type, name, offset
  std::vector<Member> members{{array(t_vec4, fcount), "c", 0}};
  if (has_int) {
    members.emplace_back(array(t_ivec4, UniformBlockInfo::kIntRegisters), "i", layout_.int_offset);
    members.emplace_back(array(t_uint, UniformBlockInfo::kBoolRegisters), "b", layout_.bool_offset);
  }
  if (has_bump) {
    const uint32_t slots = UniformBlockInfo::kBumpStages * UniformBlockInfo::kBumpSlotsPerStage;
    members.emplace_back(array(t_vec4, slots), "bumpenv", layout_.bump_offset);
  }
  std::vector<Id> types;
  for (const Member& m : members) types.push_back(std::get<0>(m));
  uniform_block_ = b.type_struct(types);
  b.decorate(uniform_block_, spv::Decoration::Block);
  for (uint32_t m = 0; m < members.size(); ++m) {
    b.member_decorate(uniform_block_, m, spv::Decoration::Offset, std::get<2>(members[m]));
    b.member_name(uniform_block_, m, std::get<1>(members[m]));
  }
  b.global_variable(b.type_pointer(SC::Uniform, uniform_block_), SC::Uniform, 0, uniform_var_);
  const bool vertex = prog.stage() == ir::ShaderStage::Vertex;
  b.decorate(uniform_var_, spv::Decoration::DescriptorSet, kDescriptorSet);
  b.decorate(uniform_var_, spv::Decoration::Binding,
             vertex ? kVertexConstantsBinding : kPixelConstantsBinding);
  b.name(uniform_block_, vertex ? "VsConstants" : "PsConstants");
  b.name(uniform_var_, vertex ? "vs_constants" : "ps_constants");
}

UniformBlockInfo uniform_block_layout(uint32_t float_slots, bool has_int, bool has_bump) {
  constexpr uint32_t kStride = UniformBlockInfo::kStride;
  UniformBlockInfo u;
  uint32_t offset = kStride * float_slots;
  if (has_int) {
    u.int_offset = offset;
    offset += kStride * UniformBlockInfo::kIntRegisters;
    u.bool_offset = offset;
    offset += kStride * UniformBlockInfo::kBoolRegisters;
  }
  if (has_bump) {
    u.bump_offset = offset;
    offset += kStride * UniformBlockInfo::kBumpStages * UniformBlockInfo::kBumpSlotsPerStage;
  }
  u.size_bytes = offset;
  return u;
}

void Emitter::emit_code() {
  fn_main_ = b.fresh_id();
  const Id fn_type = b.type_function(t_void);
  b.begin_function(t_void, fn_type, fn_main_);
  b.name(fn_main_, "d3d_main");
  b.begin_block(b.fresh_id());
  std::vector<PendingStore> pending;
  if (opt.known_ps_constants && prog.stage() == ir::ShaderStage::Pixel) {
    ir::PlainValueInputs in;
    in.constants = *opt.known_ps_constants;
    for (uint32_t s = 0; s < 16; ++s)
      if (fetches(s)) in.unorm8_stages |= 1u << s;
    in.ps1x_max = opt.conventions.ps1x_max_value;
    in.ps1x_fixed_bits = opt.conventions.ps1x_fixed_bits;
    plain_ = ir::plain_values(prog, in);
  }
  for (size_t i = 0; i < prog.code.size() && !failed; ++i) {
    const ir::Instruction& ins = prog.code[i];
    current_ = i;
    if (!ins.coissue) flush(pending);
    if (i < plan.skip.size() && plan.skip[i]) continue;
    const ir::OpInfo& info = ir::op_info(ins.op);
    if (routine_ended_ && ins.op != ir::Opcode::Label) continue;
    if (info.cls == ir::OpClass::Flow) {
      emit_flow(ins, i);
      continue;
    }
    if (ir::flow::comparison_of(ins.op)) { // setp_comp
      emit_setp(ins);
      continue;
    }
    if (ins.op == ir::Opcode::Nop) continue;
    const size_t stores = pending.size();
    if (info.cls == ir::OpClass::Texture) {
      std::optional<PendingStore> st;
      if (emit_texture(ins, st) && st) pending.push_back(*st);
    } else {
      PendingStore st;
      if (emit_arith(ins, st)) pending.push_back(st);
    }
    if (pending.size() > stores) pending.back().index = i;
    if (pending.size() > stores && ins.pred) pending.back().pred = predicate_mask(*ins.pred);
    if (pending.size() > stores && i < plain_.within_ps1x_range.size())
      pending.back().within_ps1x_range = plain_.within_ps1x_range[i];
  }
  flush(pending);
  if (!flow_.empty() && !failed) error(prog.code.back().loc, "unterminated flow control");
  for (const auto& [label, fn] : label_fns_)
    if (!labels_defined_.count(label) && !failed)
      error(prog.version_loc, "call to l" + std::to_string(label) + ", which is never defined");
  if (b.block_open()) b.op_void(Op::OpReturn, {});
  b.end_function();
}

bool Emitter::plain_factors(size_t a, size_t b, uint8_t mask) const {
  if (current_ >= plain_.sources.size() || a >= 4 || b >= 4) return false;
  const std::array<uint8_t, 4>& s = plain_.sources[current_];
  return (s[a] & s[b] & mask) == mask;
}

void Emitter::flush(std::vector<PendingStore>& pending) {
  const bool ps1x = ir::is_ps1x(prog.profile);
  for (const PendingStore& st : pending) {
    store(st, ps1x && (st.dst.file == RegFile::Temp || st.dst.file == RegFile::Texture));
    if (tracing()) trace_store(st);
  }
  pending.clear();
}

} // namespace tierlift::codegen
