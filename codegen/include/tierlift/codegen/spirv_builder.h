// A small SPIR-V module builder: ids, deduplicated types and constants, decorations,
// functions and blocks, emitted straight to words (no text, no glslang). It knows nothing of
// Direct3D; the code generator (codegen.h) drives it.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string_view>
#include <vector>

#include <spirv/unified1/spirv.hpp11>

namespace tierlift::codegen {

using Id = uint32_t;

class SpirvBuilder {
public:
  SpirvBuilder();

  Id fresh_id() { return next_id_++; }

  // --- module-level sections -------------------------------------------------------------
  void capability(spv::Capability cap);
  void extension(std::string_view name);
  Id ext_inst_import(std::string_view name);
  void memory_model(spv::AddressingModel am, spv::MemoryModel mm);
  void entry_point(spv::ExecutionModel model, Id fn, std::string_view name,
                   std::span<const Id> interface);
  void execution_mode(Id fn, spv::ExecutionMode mode, std::span<const uint32_t> literals = {});
  void name(Id id, std::string_view text);
  void member_name(Id type, uint32_t member, std::string_view text);
  void decorate(Id id, spv::Decoration d, std::span<const uint32_t> literals = {});
  void decorate(Id id, spv::Decoration d, uint32_t literal) { decorate(id, d, {&literal, 1}); }
  void member_decorate(Id type, uint32_t member, spv::Decoration d,
                       std::span<const uint32_t> literals = {});
  void member_decorate(Id type, uint32_t member, spv::Decoration d, uint32_t literal) {
    member_decorate(type, member, d, {&literal, 1});
  }

  // --- types (deduplicated, except structs: they carry their own decorations) ------------
  Id type_void();
  Id type_bool();
  Id type_float(); // 32-bit
  Id type_int(bool is_signed);
  Id type_vector(Id component, uint32_t count);
  Id type_array(Id element, Id length_const);
  Id type_runtime_array(Id element);
  Id type_struct(std::span<const Id> members);
  Id type_pointer(spv::StorageClass sc, Id pointee);
  Id type_function(Id ret, std::span<const Id> params = {});
  Id type_image(Id sampled, spv::Dim dim); // sampled, non-arrayed, single-sample
  Id type_sampled_image(Id image);

  // --- constants (deduplicated by bit pattern: -0 and NaN stay distinct) -----------------
  Id const_float(float v);
  Id const_int(int32_t v);
  Id const_uint(uint32_t v);
  Id const_bool(bool v);
  Id const_composite(Id type, std::span<const Id> parts);
  Id const_null(Id type);
  // A specialization constant is never deduplicated; the caller decorates SpecId.
  Id spec_const_float(float default_value);

  // --- global variables ------------------------------------------------------------------
  // id = 0: a fresh id; otherwise an id reserved earlier with fresh_id() (so a variable whose
  // type is only known at the end can be referenced by code emitted before).
  Id global_variable(Id pointer_type, spv::StorageClass sc, Id initializer = 0, Id id = 0);

  // --- functions and blocks --------------------------------------------------------------
  Id begin_function(Id ret_type, Id fn_type, Id fn_id = 0);
  void begin_block(Id label);
  void end_function();
  bool block_open() const { return block_open_; }

  // An instruction with a result type and result id; returns the id.
  Id op(spv::Op opcode, Id result_type, std::span<const uint32_t> operands);
  Id op(spv::Op opcode, Id result_type, std::initializer_list<uint32_t> operands) {
    return op(opcode, result_type, std::span<const uint32_t>(operands.begin(), operands.size()));
  }
  // An instruction without result (stores, branches, ...). Terminators close the block.
  void op_void(spv::Op opcode, std::span<const uint32_t> operands);
  void op_void(spv::Op opcode, std::initializer_list<uint32_t> operands) {
    op_void(opcode, std::span<const uint32_t>(operands.begin(), operands.size()));
  }
  Id ext_inst(Id set, Id result_type, uint32_t instruction, std::span<const Id> args);

  std::vector<uint32_t> finish() const;

private:
  using Words = std::vector<uint32_t>;
  static void emit(Words& out, spv::Op opcode, std::span<const uint32_t> operands);
  static void append_string(Words& operands, std::string_view s);
  // Types and constants: one id per (opcode, operands) key.
  Id dedup(spv::Op opcode, Words key_operands, bool has_type);

  Id next_id_ = 1;
  Words capabilities_, extensions_, imports_, memory_model_, entry_points_, exec_modes_;
  Words debug_, annotations_, globals_, functions_;
  std::map<Words, Id> dedup_;
  // The function under construction: its OpFunction and its blocks.
  Words fn_header_, fn_body_;
  bool in_function_ = false, block_open_ = false;
  std::vector<uint32_t> caps_seen_;
};

} // namespace tierlift::codegen
