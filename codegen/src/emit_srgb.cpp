// D3DRS_SRGBWRITEENABLE in SPIR-V (CodegenOptions::srgb_write): each of R, G, B becomes the
// byte rounding::srgb_encode_byte finds, by the same eight-step binary search over the same
// thresholds, times rounding::kSrgbByteScale. Compares only, so the byte is the interpreter's
// for every float (NaN, ±inf and denormals included: all lie below the first threshold or
// above the last, where a flushed value lies too).
#include <spirv/unified1/spirv.hpp11>

#include "tierlift/codegen/emitter.h"
#include "tierlift/rounding/rounding.h"

namespace tierlift::codegen {

using spv::Op;

Id Emitter::srgb_encode(Id color) {
  if (!srgb_table_) {
    const std::array<float, 256>& t = rounding::srgb_encode_thresholds();
    std::vector<Id> parts;
    parts.reserve(t.size());
    for (float v : t) parts.push_back(f(v));
    const Id array = b.type_array(t_float, b.const_uint(static_cast<uint32_t>(t.size())));
    const Id init = b.const_composite(array, parts);
    srgb_table_ = b.global_variable(b.type_pointer(spv::StorageClass::Private, array),
                                    spv::StorageClass::Private, init);
  }
  const Id ptr_float = b.type_pointer(spv::StorageClass::Private, t_float);
  Id out[4];
  for (uint32_t c = 0; c < 3; ++c) {
    const Id x = comp(color, c);
    Id k = b.const_uint(0);
    for (uint32_t step = 128; step >= 1; step /= 2) {
      const Id candidate = b.op(Op::OpIAdd, t_uint, {k, b.const_uint(step)});
      const Id threshold =
          b.op(Op::OpLoad, t_float, {b.op(Op::OpAccessChain, ptr_float, {srgb_table_, candidate})});
      k = b.op(Op::OpSelect, t_uint,
               {cmp(Op::OpFOrdGreaterThanEqual, x, threshold, 1), candidate, k});
    }
    out[c] = fmul(b.op(Op::OpConvertUToF, t_float, {k}), f(rounding::kSrgbByteScale), 1);
  }
  out[3] = comp(color, 3);
  return compose(out[0], out[1], out[2], out[3]);
}

} // namespace tierlift::codegen
