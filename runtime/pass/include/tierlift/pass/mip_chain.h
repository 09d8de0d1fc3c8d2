// Mip chains of 2D textures (NUMERICS.md "Mip levels and LOD", M4): a binding's levels,
// checked, or generated from its level 0 with one documented filter.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"

namespace tierlift::pass {

// The number of levels of a full chain of a w×h texture: 1 + floor(log2(max(w, h))), each
// level max(1, floor(previous / 2)) on each side down to 1×1.
uint32_t full_chain_length(uint32_t width, uint32_t height);

// The size of level `k` of a w×h texture: max(1, w >> k) by max(1, h >> k).
uint32_t level_extent(uint32_t size, uint32_t level);

// Levels 0..count − 1 from `base` (count 0: the full chain; more than the full chain is
// clamped to it). Level 0 is `base` itself; level k + 1 is a 2×2 box of level k, in float:
// texel (i, j) is ((a + b) + (c + d))·¼ of the texels (2i, 2j), (2i + 1, 2j), (2i, 2j + 1),
// (2i + 1, 2j + 1), each sum of two a float add (the order is fixed, so the result is too).
// An odd side drops its last row or column (floor halving: texel 2i + 1 always exists there),
// and a side already 1 texel long is read twice (index clamped), so its texel averages itself.
std::vector<std::shared_ptr<const img::Image>> generate_mips(std::shared_ptr<const img::Image> base,
                                                             uint32_t count);

// A 2D binding with the levels given (level 0 first): each level must have pixels and the
// size max(1, floor(previous / 2)) on each side, and there can be at most a full chain; an
// error (rule "texture", subject "mips") says which level is wrong.
ir::Result<TextureBinding> mipmapped_binding(std::vector<std::shared_ptr<const img::Image>> levels);

// The levels a binding holds: its `levels` when it has them, else 1 (its image alone).
inline uint32_t level_count(const TextureBinding& b) {
  return b.levels.empty() ? 1u : static_cast<uint32_t>(b.levels.size());
}
// Level k of a binding (level 0 is b.image); k must be < level_count(b).
inline const img::Image& level_image(const TextureBinding& b, uint32_t k) {
  return b.levels.empty() ? *b.image : *b.levels[k];
}

} // namespace tierlift::pass
