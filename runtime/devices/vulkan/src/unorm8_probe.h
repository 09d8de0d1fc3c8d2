// Internal: how this device returns RGBA8 UNORM texels to a shader, read once when the device
// is created, so that in-place RGBA8 reads decode them with the cheapest exact decode
// (codegen/unorm8_decode.h).
#pragma once

#include <vector>

#include "tierlift/ir/result.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::vulkan {

// The device's value of every level, as an in-place read returns it with no decode (the
// caller sets Device::Impl::unorm8_decode to None first): a 16 × 16 RGBA8 texture whose
// texel p holds level (p + 64c) % 256 in channel c, copied texel for texel into an RGBA32F
// target through the device's own point read. values[i] is the value of level i % 256.
ir::Result<std::vector<float>> read_unorm8_levels(Device& device);

} // namespace tierlift::vulkan
