// Mip chains: sizes, the box filter that generates them, the checks (mip_chain.h).
#include "tierlift/pass/mip_chain.h"

#include <algorithm>

#include <fmt/format.h>

namespace tierlift::pass {

uint32_t full_chain_length(uint32_t width, uint32_t height) {
  uint32_t n = 1;
  for (uint32_t side = std::max(width, height); side > 1; side /= 2) ++n;
  return n;
}

uint32_t level_extent(uint32_t size, uint32_t level) {
  return level >= 32 ? 1u : std::max(1u, size >> level);
}

namespace {

// Level k + 1 of `prev` by the 2×2 box (mip_chain.h).
std::shared_ptr<const img::Image> halve(const img::Image& prev) {
  const uint32_t w = std::max(1u, prev.width / 2), h = std::max(1u, prev.height / 2);
  auto next = std::make_shared<img::Image>(w, h, prev.format);
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i) {
      const uint32_t x0 = std::min(2 * i, prev.width - 1), x1 = std::min(2 * i + 1, prev.width - 1);
      const uint32_t y0 = std::min(2 * j, prev.height - 1),
                     y1 = std::min(2 * j + 1, prev.height - 1);
      const float *a = prev.at(x0, y0), *b = prev.at(x1, y0), *c = prev.at(x0, y1),
                  *d = prev.at(x1, y1);
      float* out = next->at(i, j);
      for (int k = 0; k < 4; ++k) out[k] = ((a[k] + b[k]) + (c[k] + d[k])) * 0.25f;
    }
  return next;
}

} // namespace

std::vector<std::shared_ptr<const img::Image>> generate_mips(std::shared_ptr<const img::Image> base,
                                                             uint32_t count) {
  std::vector<std::shared_ptr<const img::Image>> levels;
  if (!base || base->width == 0 || base->height == 0) return levels;
  const uint32_t full = full_chain_length(base->width, base->height);
  const uint32_t n = count == 0 ? full : std::min(count, full);
  levels.push_back(std::move(base));
  while (levels.size() < n) levels.push_back(halve(*levels.back()));
  return levels;
}

ir::Result<TextureBinding>
mipmapped_binding(std::vector<std::shared_ptr<const img::Image>> levels) {
  auto bad = [](std::string message) { return ir::fail("texture", "mips", std::move(message)); };
  if (levels.empty() || !levels[0] || levels[0]->width == 0 || levels[0]->height == 0)
    return bad("a mip chain needs a level 0 with pixels");
  const uint32_t w = levels[0]->width, h = levels[0]->height;
  const uint32_t full = full_chain_length(w, h);
  if (levels.size() > full)
    return bad(
        fmt::format("a {}x{} texture has at most {} levels, not {}", w, h, full, levels.size()));
  for (uint32_t k = 1; k < levels.size(); ++k) {
    const uint32_t ew = level_extent(w, k), eh = level_extent(h, k);
    if (!levels[k] || levels[k]->width != ew || levels[k]->height != eh ||
        levels[k]->rgba.size() != size_t{ew} * eh * 4)
      return bad(fmt::format("level {} must be {}x{} (each side max(1, floor(previous / 2))), "
                             "not {}x{}",
                             k, ew, eh, levels[k] ? levels[k]->width : 0,
                             levels[k] ? levels[k]->height : 0));
  }
  TextureBinding b;
  b.image = levels[0];
  if (levels.size() > 1) b.levels = std::move(levels);
  return b;
}

} // namespace tierlift::pass
