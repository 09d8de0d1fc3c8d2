// How a module turns the value a device returns for an RGBA8 UNORM texel (level k) into
// k/255.0f correctly rounded, the value the interpreter reads (CodegenOptions::
// stage_fetch_unorm8). Devices convert the byte their own way: lavapipe returns a value one
// ulp away from k/255 for 126 of the 256 levels. The Vulkan device reads every level once
// when it is created, with no decode, and picks the cheapest decode that gives k/255.0f for
// all 256 (choose_unorm8_decode); decode_on_host computes what each decode's SPIR-V
// computes (emit_texture.cpp), one fp32 operation for one.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace tierlift::codegen {

enum class Unorm8Decode : uint8_t {
  // The device's value already is k/255.0f (or, while the device reads every level to
  // choose, the raw value is wanted): no operation.
  None,
  // fl(fl(v·kTwoMultiply[0])·kTwoMultiply[1]): two multiplies. Exact for both ways lavapipe
  // is known to convert (fl(k·fl(1/255)) and fl(fl(k/256)·fl(256/255))), found by searching
  // the factor pairs near 1 and checked here for all 256 levels of each (unorm8_decode_test).
  TwoMultiply,
  // General: k = roundEven(v·255), then fl(fl(k·65793 + v)·2^-24) (2^24/255 = 65793 +
  // 1/255). Exact whenever v is within a few ulps of k/255: five operations.
  RoundAndRebuild,
};

inline constexpr std::array<float, 2> kTwoMultiply = {1.00066864f, 0.999331772f};

// What the decode's SPIR-V computes from the device's value v (fp32, no contraction).
float decode_on_host(Unorm8Decode d, float v);

// The cheapest decode that maps every value the device returned to k/255.0f bit for bit,
// where values[i] is the device's value of level k = i % 256 (each level at least once: a
// multiple of 256 values, several reads of each level, from each channel), or nullopt when
// none does (the device then reads RGBA8 textures through an exact float copy).
std::optional<Unorm8Decode> choose_unorm8_decode(std::span<const float> values);

const char* unorm8_decode_name(Unorm8Decode d);

} // namespace tierlift::codegen
