// D3DTADDRESS: how a sampler maps a texel index outside the texture back into it
// (docs/d3d9-rules.md §10.2). The one definition of the rule: the CPU device's samplers and
// the analytic model both read it.
#pragma once

#include <cstdint>
#include <optional>

namespace tierlift::pass {

enum class AddressMode : uint8_t { Wrap, Mirror, Clamp, Border, MirrorOnce };

// The texel index `mode` turns `i` into on an axis of `n` texels, or nullopt when the border
// colour is read instead (Border with `i` outside [0, n−1], or an empty axis). Indices inside
// the texture are left alone by every mode.
std::optional<int64_t> address_texel(AddressMode mode, int64_t i, int64_t n);

} // namespace tierlift::pass
