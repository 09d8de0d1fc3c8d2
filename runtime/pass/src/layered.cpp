// Cube and volume bindings: the checks every caller of layered_binding shares.
#include <fmt/format.h>

#include "tierlift/pass/pass.h"

namespace tierlift::pass {

ir::Result<TextureBinding> layered_binding(TextureShape shape,
                                           std::vector<std::shared_ptr<const img::Image>> layers) {
  auto bad = [](std::string message) { return ir::fail("texture", "shape", std::move(message)); };
  const char* what = shape == TextureShape::Cube ? "cube texture" : "volume texture";
  if (shape == TextureShape::Tex2D) return bad("a 2D texture has no layers");
  if (shape == TextureShape::Cube && layers.size() != 6)
    return bad(fmt::format("a cube texture has 6 faces, not {}", layers.size()));
  if (layers.empty()) return bad("a volume texture needs at least one slice");
  for (size_t k = 0; k < layers.size(); ++k) {
    if (!layers[k] || layers[k]->width == 0 || layers[k]->height == 0)
      return bad(fmt::format("{} layer {} has no pixels", what, k));
    if (layers[k]->width != layers[0]->width || layers[k]->height != layers[0]->height)
      return bad(fmt::format("{} layer {} is {}x{}, layer 0 {}x{}: all layers have one size", what,
                             k, layers[k]->width, layers[k]->height, layers[0]->width,
                             layers[0]->height));
  }
  if (shape == TextureShape::Cube && layers[0]->width != layers[0]->height)
    return bad(
        fmt::format("cube faces are square, not {}x{}", layers[0]->width, layers[0]->height));
  TextureBinding b;
  b.shape = shape;
  b.image = layers[0];
  b.layers = std::move(layers);
  return b;
}

} // namespace tierlift::pass
