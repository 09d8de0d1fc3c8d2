// The RGBA8 read decodes (unorm8_decode.h), computed on the host.
#include "tierlift/codegen/unorm8_decode.h"

#include <bit>
#include <cmath>

namespace tierlift::codegen {
namespace {

// One fp32 operation each: volatile keeps the compiler from contracting or reordering them.
float mul(float a, float b) {
  volatile float r = a * b;
  return r;
}
float add(float a, float b) {
  volatile float r = a + b;
  return r;
}

} // namespace

float decode_on_host(Unorm8Decode d, float v) {
  switch (d) {
  case Unorm8Decode::None: return v;
  case Unorm8Decode::TwoMultiply: return mul(mul(v, kTwoMultiply[0]), kTwoMultiply[1]);
  case Unorm8Decode::RoundAndRebuild: {
    const float k = std::nearbyint(mul(v, 255.0f)); // ties to even, the default mode
    return mul(add(mul(k, 65793.0f), v), 0x1p-24f);
  }
  }
  return v;
}

std::optional<Unorm8Decode> choose_unorm8_decode(std::span<const float> values) {
  if (values.empty() || values.size() % 256 != 0) return std::nullopt;
  for (const Unorm8Decode d :
       {Unorm8Decode::None, Unorm8Decode::TwoMultiply, Unorm8Decode::RoundAndRebuild}) {
    bool exact = true;
    for (size_t i = 0; i < values.size() && exact; ++i) {
      const float want = static_cast<float>(static_cast<double>(i % 256) / 255.0);
      exact =
          std::bit_cast<uint32_t>(decode_on_host(d, values[i])) == std::bit_cast<uint32_t>(want);
    }
    if (exact) return d;
  }
  return std::nullopt;
}

const char* unorm8_decode_name(Unorm8Decode d) {
  switch (d) {
  case Unorm8Decode::None: return "none";
  case Unorm8Decode::TwoMultiply: return "two multiplies";
  case Unorm8Decode::RoundAndRebuild: return "round and rebuild";
  }
  return "?";
}

} // namespace tierlift::codegen
