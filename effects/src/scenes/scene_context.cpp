// Reads a scene's rendering context (glow_context.h): the top-level "glow_image" (a separate
// glow render of the scene) and "glow"/"fog" (the glow fog). Both images are read here, so a
// missing file or one of another size is reported where the scene names it.
#include <fmt/format.h>

#include "scene_parts.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

constexpr std::string_view kFogKeys[] = {"start", "end", "color", "depth"};
constexpr NumberRange kDepth{-1e6, 1e6};
// The fog colour is a colour the listings blend toward: ps.1.x constants hold at most 1.
constexpr NumberRange kFogChannel{0, 1};

// A PNG or PFM of the scene's size, named by the string at `at`; null after an error.
// `*file` is set to the path read (an input no output may replace).
std::shared_ptr<const img::Image> read_scene_sized(const Json& v, const std::string& at,
                                                   FieldChecker& c, const std::string& base_dir,
                                                   const EffectParams& p, std::string* file) {
  std::optional<std::string> name = c.string(v, at);
  if (!name) return nullptr;
  if (name->empty()) {
    c.error(at, "is empty; expected a PNG or PFM file");
    return nullptr;
  }
  *file = resolve_path(base_dir, *name);
  img::ImageResult image = img::read_image(*file);
  if (!image) {
    const std::string why = image.message().substr(0, image.message().find('\n'));
    c.error(at, fmt::format("cannot read the image: {}", why));
    return nullptr;
  }
  if (image->width != p.width || image->height != p.height) {
    c.error(at, fmt::format("the image is {}x{} but the scene is {}x{}; it must be the scene's "
                            "size",
                            image->width, image->height, p.width, p.height));
    return nullptr;
  }
  image->format = img::Format::RGBA32F; // 8-bit values k/255 are exact floats already
  return std::make_shared<const img::Image>(std::move(*image));
}

} // namespace

std::span<const std::string_view> scene_fog_keys() {
  return kFogKeys;
}

void read_glow_image(const Json& v, FieldChecker& c, const std::string& base_dir, Scene& s) {
  s.params.context.glow_image =
      read_scene_sized(v, "/glow_image", c, base_dir, s.params, &s.params.context.glow_image_file);
  if (s.params.context.glow_image)
    for (const std::string& w : image_warnings(*s.params.context.glow_image))
      s.warnings.push_back("glow image: " + w);
}

void read_fog(const Json& v, const std::string& at, FieldChecker& c, const std::string& base_dir,
              EffectParams& p) {
  if (!c.object(v, at, kFogKeys, std::span(kFogKeys).first(2))) return;
  GlowFog fog;
  fog.on = true;
  std::optional<double> start, end;
  if (const Json* s = member(v, "start")) start = c.number(*s, at + "/start", kDepth);
  if (const Json* e = member(v, "end")) end = c.number(*e, at + "/end", kDepth);
  if (start && end && !(*start < *end))
    c.error(at + "/end",
            fmt::format("{} is not beyond start {}: the fog needs start < end", *end, *start));
  fog.start = start.value_or(fog.start);
  fog.end = end.value_or(fog.end);
  if (const Json* col = member(v, "color"))
    c.numbers(*col, at + "/color", kFogChannel, fog.color, "[r, g, b] (three numbers in 0..1)");
  if (const Json* d = member(v, "depth"))
    fog.depth = read_scene_sized(*d, at + "/depth", c, base_dir, p, &fog.depth_file);
  if (c.failed()) return;
  // Tiers dx8 and dx7 draw the fog in ps.1.1: its constants must fit [-1, 1].
  if (p.tier == Tier::Dx8 || p.tier == Tier::Dx7)
    if (std::string why = fog_ps1x_limit(fog); !why.empty())
      c.error(at + "/end", fmt::format("tier {}: {}", tier_name(p.tier), why));
  p.context.fog = std::move(fog);
}

} // namespace tierlift::effects
