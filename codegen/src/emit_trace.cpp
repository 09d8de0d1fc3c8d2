// CodegenOptions::trace: a pixel module that records, for one pixel, the value of every
// instruction's destination register after the instruction wrote it (codegen.h, TracePixel).
// The entry point sets a Private bool "this invocation is the traced pixel" from
// gl_FragCoord; after each register store the module branches on it and, at that pixel
// only, writes the register into the instruction's entry of a storage buffer and counts the
// run. Nothing else changes: the stores read registers the program already wrote, so the
// image is the untraced module's, and without the option none of this is emitted.
#include "tierlift/codegen/emitter.h"

namespace tierlift::codegen {

using ir::RegFile;
using spv::Op;
using SC = spv::StorageClass;

bool Emitter::tracing() const {
  return opt.trace.has_value() && prog.stage() == ir::ShaderStage::Pixel;
}

// struct TraceEntry { vec4 value; uint hits; }; buffer TraceBuffer { TraceEntry e[]; };
// The entry struct is never deduplicated, so the runtime array over it (stride 32) is a type
// of its own and its ArrayStride cannot clash with the uniform block's arrays.
void Emitter::declare_trace_buffer() {
  if (trace_var_) return;
  const Id t_u = t_uint;
  const Id entry = b.type_struct(std::vector<Id>{t_vec4, t_u});
  b.member_decorate(entry, 0, spv::Decoration::Offset, 0);
  b.member_decorate(entry, 1, spv::Decoration::Offset, 16);
  b.name(entry, "TraceEntry");
  b.member_name(entry, 0, "value");
  b.member_name(entry, 1, "hits");
  const Id array = b.type_runtime_array(entry);
  b.decorate(array, spv::Decoration::ArrayStride, kTraceEntryBytes);
  const Id block = b.type_struct(std::vector<Id>{array});
  b.decorate(block, spv::Decoration::Block);
  b.member_decorate(block, 0, spv::Decoration::Offset, 0);
  b.name(block, "TraceBuffer");
  b.member_name(block, 0, "entries");
  trace_var_ = b.global_variable(b.type_pointer(SC::StorageBuffer, block), SC::StorageBuffer);
  b.decorate(trace_var_, spv::Decoration::DescriptorSet, kDescriptorSet);
  b.decorate(trace_var_, spv::Decoration::Binding, opt.trace->binding);
  b.name(trace_var_, "trace");
  trace_ptr_vec4_ = b.type_pointer(SC::StorageBuffer, t_vec4);
  trace_ptr_uint_ = b.type_pointer(SC::StorageBuffer, t_u);
}

void Emitter::trace_begin_entry() {
  if (!trace_flag_) return; // no instruction records: nothing to decide
  // gl_FragCoord is the pixel's centre (x + 0.5, y + 0.5) whatever the D3D9 centre rule
  // (the device moves the geometry, not the sample point): truncated, the pixel's index.
  const Id frag = b.global_variable(b.type_pointer(SC::Input, t_vec4), SC::Input);
  b.decorate(frag, spv::Decoration::BuiltIn, static_cast<uint32_t>(spv::BuiltIn::FragCoord));
  b.name(frag, "frag_coord");
  interface_ids_.push_back(frag);
  const Id coord = b.op(Op::OpLoad, t_vec4, {frag});
  auto index_is = [&](uint32_t component, uint32_t want) {
    const Id i = b.op(Op::OpConvertFToU, t_uint, {comp(coord, component)});
    return b.op(Op::OpIEqual, t_bool, {i, b.const_uint(want)});
  };
  const Id here =
      b.op(Op::OpLogicalAnd, t_bool, {index_is(0, opt.trace->x), index_is(1, opt.trace->y)});
  b.op_void(Op::OpStore, {trace_flag_, here});
}

void Emitter::trace_store(const PendingStore& st) {
  if (!b.block_open() || (st.mask & 0xF) == 0) return; // nothing was stored
  declare_trace_buffer();
  if (!trace_flag_) {
    trace_flag_ =
        b.global_variable(b.type_pointer(SC::Private, t_bool), SC::Private, b.const_bool(false));
    b.name(trace_flag_, "traced_pixel");
  }
  const auto index = static_cast<uint32_t>(st.index);
  if (trace_points_.empty() || trace_points_.back() != index) trace_points_.push_back(index);
  const Id then = b.fresh_id(), merge = b.fresh_id();
  const Id here = b.op(Op::OpLoad, t_bool, {trace_flag_});
  b.op_void(Op::OpSelectionMerge,
            {merge, static_cast<uint32_t>(spv::SelectionControlMask::MaskNone)});
  b.op_void(Op::OpBranchConditional, {here, then, merge});
  b.begin_block(then);
  const bool addr = st.dst.file == RegFile::Addr;
  const Id var = register_var(st.dst.file, addr ? 0 : st.dst.index);
  Id value = b.op(Op::OpLoad, addr ? t_ivec4 : t_vec4, {var});
  if (addr) value = b.op(Op::OpConvertSToF, t_vec4, {value});
  const Id entry = b.const_uint(index);
  const Id value_ptr = b.op(Op::OpAccessChain, trace_ptr_vec4_,
                            {trace_var_, b.const_uint(0), entry, b.const_uint(0)});
  b.op_void(Op::OpStore, {value_ptr, value});
  const Id hits_ptr = b.op(Op::OpAccessChain, trace_ptr_uint_,
                           {trace_var_, b.const_uint(0), entry, b.const_uint(1)});
  const Id hits = b.op(Op::OpLoad, t_uint, {hits_ptr});
  b.op_void(Op::OpStore, {hits_ptr, b.op(Op::OpIAdd, t_uint, {hits, b.const_uint(1)})});
  b.op_void(Op::OpBranch, {merge});
  b.begin_block(merge);
}

} // namespace tierlift::codegen
