// Word-level SPIR-V emission. Sections are kept apart and concatenated in the order the
// specification's "logical layout of a module" requires (2.4), so callers may declare a
// type or constant in the middle of a function body.
#include "tierlift/codegen/spirv_builder.h"

#include <algorithm>
#include <bit>

namespace tierlift::codegen {

using spv::Op;

namespace {

bool is_block_terminator(spv::Op opcode) {
  switch (opcode) {
  case Op::OpBranch:
  case Op::OpBranchConditional:
  case Op::OpSwitch:
  case Op::OpReturn:
  case Op::OpReturnValue:
  case Op::OpKill:
  case Op::OpUnreachable:
  case Op::OpTerminateInvocation: return true;
  default: return false;
  }
}

} // namespace

SpirvBuilder::SpirvBuilder() = default;

void SpirvBuilder::emit(Words& out, spv::Op opcode, std::span<const uint32_t> operands) {
  const auto count = static_cast<uint32_t>(operands.size() + 1);
  out.push_back((count << 16) | static_cast<uint32_t>(opcode));
  out.insert(out.end(), operands.begin(), operands.end());
}

void SpirvBuilder::append_string(Words& operands, std::string_view s) {
  // UTF-8, nul-terminated, padded with nuls to a whole word (little-endian packing).
  const size_t words = s.size() / 4 + 1;
  const size_t base = operands.size();
  operands.resize(base + words, 0);
  for (size_t i = 0; i < s.size(); ++i)
    operands[base + i / 4] |= static_cast<uint32_t>(static_cast<unsigned char>(s[i]))
                              << (8 * (i % 4));
}

void SpirvBuilder::capability(spv::Capability cap) {
  const auto c = static_cast<uint32_t>(cap);
  if (std::find(caps_seen_.begin(), caps_seen_.end(), c) != caps_seen_.end()) return;
  caps_seen_.push_back(c);
  emit(capabilities_, Op::OpCapability, {&c, 1});
}

void SpirvBuilder::extension(std::string_view ext) {
  Words ops;
  append_string(ops, ext);
  emit(extensions_, Op::OpExtension, ops);
}

Id SpirvBuilder::ext_inst_import(std::string_view set) {
  Id id = fresh_id();
  Words ops{id};
  append_string(ops, set);
  emit(imports_, Op::OpExtInstImport, ops);
  return id;
}

void SpirvBuilder::memory_model(spv::AddressingModel am, spv::MemoryModel mm) {
  memory_model_.clear();
  const uint32_t ops[] = {static_cast<uint32_t>(am), static_cast<uint32_t>(mm)};
  emit(memory_model_, Op::OpMemoryModel, ops);
}

void SpirvBuilder::entry_point(spv::ExecutionModel model, Id fn, std::string_view ep_name,
                               std::span<const Id> interface) {
  Words ops{static_cast<uint32_t>(model), fn};
  append_string(ops, ep_name);
  ops.insert(ops.end(), interface.begin(), interface.end());
  emit(entry_points_, Op::OpEntryPoint, ops);
}

void SpirvBuilder::execution_mode(Id fn, spv::ExecutionMode mode,
                                  std::span<const uint32_t> literals) {
  Words ops{fn, static_cast<uint32_t>(mode)};
  ops.insert(ops.end(), literals.begin(), literals.end());
  emit(exec_modes_, Op::OpExecutionMode, ops);
}

void SpirvBuilder::name(Id id, std::string_view text) {
  Words ops{id};
  append_string(ops, text);
  emit(debug_, Op::OpName, ops);
}

void SpirvBuilder::member_name(Id type, uint32_t member, std::string_view text) {
  Words ops{type, member};
  append_string(ops, text);
  emit(debug_, Op::OpMemberName, ops);
}

void SpirvBuilder::decorate(Id id, spv::Decoration d, std::span<const uint32_t> literals) {
  Words ops{id, static_cast<uint32_t>(d)};
  ops.insert(ops.end(), literals.begin(), literals.end());
  emit(annotations_, Op::OpDecorate, ops);
}

void SpirvBuilder::member_decorate(Id type, uint32_t member, spv::Decoration d,
                                   std::span<const uint32_t> literals) {
  Words ops{type, member, static_cast<uint32_t>(d)};
  ops.insert(ops.end(), literals.begin(), literals.end());
  emit(annotations_, Op::OpMemberDecorate, ops);
}

Id SpirvBuilder::dedup(spv::Op opcode, Words key_operands, bool has_type) {
  Words key{static_cast<uint32_t>(opcode)};
  key.insert(key.end(), key_operands.begin(), key_operands.end());
  if (auto it = dedup_.find(key); it != dedup_.end()) return it->second;
  const Id id = fresh_id();
  Words ops;
  if (has_type) {
    ops.push_back(key_operands[0]);
    ops.push_back(id);
    ops.insert(ops.end(), key_operands.begin() + 1, key_operands.end());
  } else {
    ops.push_back(id);
    ops.insert(ops.end(), key_operands.begin(), key_operands.end());
  }
  emit(globals_, opcode, ops);
  dedup_.emplace(std::move(key), id);
  return id;
}

Id SpirvBuilder::type_void() {
  return dedup(Op::OpTypeVoid, {}, false);
}
Id SpirvBuilder::type_bool() {
  return dedup(Op::OpTypeBool, {}, false);
}
Id SpirvBuilder::type_float() {
  return dedup(Op::OpTypeFloat, {32}, false);
}
Id SpirvBuilder::type_int(bool is_signed) {
  return dedup(Op::OpTypeInt, {32, is_signed ? 1u : 0u}, false);
}
Id SpirvBuilder::type_vector(Id component, uint32_t count) {
  return dedup(Op::OpTypeVector, {component, count}, false);
}
Id SpirvBuilder::type_array(Id element, Id length_const) {
  // Arrays are decorated with ArrayStride by the caller; one stride per (element, length)
  // is all this project needs, so sharing them is safe.
  return dedup(Op::OpTypeArray, {element, length_const}, false);
}
Id SpirvBuilder::type_runtime_array(Id element) {
  // As type_array: the caller decorates ArrayStride, one stride per element type.
  return dedup(Op::OpTypeRuntimeArray, {element}, false);
}
Id SpirvBuilder::type_struct(std::span<const Id> members) {
  const Id id = fresh_id();
  Words ops{id};
  ops.insert(ops.end(), members.begin(), members.end());
  emit(globals_, Op::OpTypeStruct, ops);
  return id;
}
Id SpirvBuilder::type_pointer(spv::StorageClass sc, Id pointee) {
  return dedup(Op::OpTypePointer, {static_cast<uint32_t>(sc), pointee}, false);
}
Id SpirvBuilder::type_function(Id ret, std::span<const Id> params) {
  Words key{ret};
  key.insert(key.end(), params.begin(), params.end());
  return dedup(Op::OpTypeFunction, std::move(key), false);
}
Id SpirvBuilder::type_image(Id sampled, spv::Dim dim) {
  // depth 0, arrayed 0, MS 0, sampled 1 (with a sampler), format Unknown.
  return dedup(Op::OpTypeImage, {sampled, static_cast<uint32_t>(dim), 0, 0, 0, 1, 0}, false);
}
Id SpirvBuilder::type_sampled_image(Id image) {
  return dedup(Op::OpTypeSampledImage, {image}, false);
}

Id SpirvBuilder::const_float(float v) {
  return dedup(Op::OpConstant, {type_float(), std::bit_cast<uint32_t>(v)}, true);
}
Id SpirvBuilder::const_int(int32_t v) {
  return dedup(Op::OpConstant, {type_int(true), static_cast<uint32_t>(v)}, true);
}
Id SpirvBuilder::const_uint(uint32_t v) {
  return dedup(Op::OpConstant, {type_int(false), v}, true);
}
Id SpirvBuilder::const_bool(bool v) {
  return dedup(v ? Op::OpConstantTrue : Op::OpConstantFalse, {type_bool()}, true);
}
Id SpirvBuilder::const_composite(Id type, std::span<const Id> parts) {
  Words key{type};
  key.insert(key.end(), parts.begin(), parts.end());
  return dedup(Op::OpConstantComposite, std::move(key), true);
}
Id SpirvBuilder::const_null(Id type) {
  return dedup(Op::OpConstantNull, {type}, true);
}

Id SpirvBuilder::spec_const_float(float default_value) {
  const Id id = fresh_id();
  const uint32_t ops[] = {type_float(), id, std::bit_cast<uint32_t>(default_value)};
  emit(globals_, Op::OpSpecConstant, ops);
  return id;
}
Id SpirvBuilder::global_variable(Id pointer_type, spv::StorageClass sc, Id initializer, Id id) {
  if (!id) id = fresh_id();
  Words ops{pointer_type, id, static_cast<uint32_t>(sc)};
  if (initializer) ops.push_back(initializer);
  emit(globals_, Op::OpVariable, ops);
  return id;
}

Id SpirvBuilder::begin_function(Id ret_type, Id fn_type, Id fn_id) {
  const Id id = fn_id ? fn_id : fresh_id();
  fn_header_.clear();
  fn_body_.clear();
  const uint32_t ops[] = {ret_type, id, static_cast<uint32_t>(spv::FunctionControlMask::MaskNone),
                          fn_type};
  emit(fn_header_, Op::OpFunction, ops);
  in_function_ = true;
  block_open_ = false;
  return id;
}

void SpirvBuilder::begin_block(Id label) {
  emit(fn_body_, Op::OpLabel, {&label, 1});
  block_open_ = true;
}

void SpirvBuilder::end_function() {
  emit(fn_body_, Op::OpFunctionEnd, {});
  functions_.insert(functions_.end(), fn_header_.begin(), fn_header_.end());
  functions_.insert(functions_.end(), fn_body_.begin(), fn_body_.end());
  in_function_ = false;
  block_open_ = false;
}

Id SpirvBuilder::op(spv::Op opcode, Id result_type, std::span<const uint32_t> operands) {
  const Id id = fresh_id();
  Words ops{result_type, id};
  ops.insert(ops.end(), operands.begin(), operands.end());
  emit(fn_body_, opcode, ops);
  return id;
}

void SpirvBuilder::op_void(spv::Op opcode, std::span<const uint32_t> operands) {
  emit(fn_body_, opcode, operands);
  if (is_block_terminator(opcode)) block_open_ = false;
}

Id SpirvBuilder::ext_inst(Id set, Id result_type, uint32_t instruction, std::span<const Id> args) {
  Words ops{set, instruction};
  ops.insert(ops.end(), args.begin(), args.end());
  return op(Op::OpExtInst, result_type, ops);
}

std::vector<uint32_t> SpirvBuilder::finish() const {
  Words out{spv::MagicNumber, 0x00010300 /* SPIR-V 1.3: Vulkan 1.1 */, 0 /* generator */,
            next_id_ /* bound */, 0};
  for (const Words* w : {&capabilities_, &extensions_, &imports_, &memory_model_, &entry_points_,
                         &exec_modes_, &debug_, &annotations_, &globals_, &functions_})
    out.insert(out.end(), w->begin(), w->end());
  return out;
}

} // namespace tierlift::codegen
