// Reads a scene's JSON text: syntax, the top-level keys ("image", "size"), the scene image
// (to learn its size and to report a missing or broken PNG where the scene names it), and
// hands "glow" to scene_glow.cpp. Every problem is a diagnostic at the field's position.
#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "scene_parts.h"
#include "tierlift/effects/scenes/default_scene.h"
#include "tierlift/effects/scenes/scene.h"
#include "tierlift/image/io.h"

namespace tierlift::effects {
namespace {

constexpr std::string_view kSceneKeys[] = {"$schema", "description", "image",  "size",
                                           "glow",    "effect",      "radial", "outline",
                                           "glsl",    "glow_image"};
constexpr size_t kMaxSceneBytes = size_t{1} << 20; // a scene is a few hundred bytes
constexpr int kMaxNesting = 32;                    // a scene nests 5 deep

struct Size {
  uint32_t width = 0, height = 0;
};

// nlohmann's message without its "[json.exception…] parse error at line…, column…:" head:
// the position is ours.
std::string syntax_message(const Json::parse_error& e) {
  std::string_view what = e.what();
  const size_t at = what.find("syntax error");
  return std::string(at == std::string_view::npos ? what : what.substr(at));
}

std::optional<Size> read_size(const Json& v, FieldChecker& c) {
  if (!v.is_array() || v.size() != 2) {
    c.error("/size", fmt::format("{} is not [width, height]", FieldChecker::shown(v)));
    return std::nullopt;
  }
  auto w = c.integer(v[0], "/size/0", 1, img::kMaxDimension);
  auto h = c.integer(v[1], "/size/1", 1, img::kMaxDimension);
  if (!w || !h) return std::nullopt;
  return Size{uint32_t(*w), uint32_t(*h)};
}

// "image" and "size" → scene.image, params.width/height, the image's warnings.
void read_image(const Json& j, const std::string& base_dir, FieldChecker& c, Scene& s,
                std::vector<std::string>& warnings) {
  std::optional<Size> size;
  const Json* size_json = member(j, "size");
  if (size_json) size = read_size(*size_json, c);
  std::string image(kBuiltinNeon);
  if (const Json* v = member(j, "image")) {
    std::optional<std::string> name = c.string(*v, "/image");
    if (!name) return;
    image = *name;
  }
  if (image.starts_with("builtin:")) {
    if (image != kBuiltinNeon) {
      c.error("/image",
              fmt::format("\"{}\" is not a built-in image; expected \"{}\" or a PNG or PFM file",
                          image, kBuiltinNeon));
      return;
    }
    s.image = image;
    if (size) {
      s.params.width = size->width;
      s.params.height = size->height;
    }
    return;
  }
  if (image.empty()) {
    c.error("/image", fmt::format("is empty; expected \"{}\" or a PNG or PFM file", kBuiltinNeon));
    return;
  }
  s.image = resolve_path(base_dir, image);
  img::ImageResult png = img::read_image(s.image); // PNG, or PFM for HDR values
  if (!png) {
    // The image's own first line (a PFM header error is "PATH:LINE:COL: why" and then the
    // quoted header line: the scene's diagnostic quotes the scene's line instead).
    const std::string why = png.message().substr(0, png.message().find('\n'));
    c.error("/image", fmt::format("cannot read the image: {}", why));
    return;
  }
  s.params.width = png->width;
  s.params.height = png->height;
  if (size_json && size && (size->width != s.params.width || size->height != s.params.height))
    c.error("/size", fmt::format("{} does not match the image, which is {}x{} (\"size\" may be "
                                 "left out)",
                                 FieldChecker::shown(*size_json), s.params.width, s.params.height));
  warnings = image_warnings(*png);
}

void read_scene(const Json& j, const std::string& base_dir, FieldChecker& c, Scene& s) {
  if (!j.is_object()) {
    c.error("", fmt::format("a scene is a JSON object {{\"image\": …, \"glow\": {{…}}}}, not {}",
                            j.is_array() ? "an array" : FieldChecker::shown(j)));
    return;
  }
  c.object(j, "", kSceneKeys);
  if (const Json* v = member(j, "$schema")) c.string(*v, "/$schema");
  if (const Json* v = member(j, "description")) c.string(*v, "/description");
  std::vector<std::string> image_warns;
  read_image(j, base_dir, c, s, image_warns);
  // The glow render's size is the scene's: read once the image has set it.
  const Json* glow_image = member(j, "glow_image");
  if (glow_image && !c.failed()) read_glow_image(*glow_image, c, base_dir, s);
  const Json* glow = member(j, "glow");
  if (glow) read_glow(*glow, c, base_dir, s.params);
  read_effect(j, c, base_dir, s);
  if (s.params.motion.on() && s.image != kBuiltinNeon)
    c.error("/glow/motion", "moves the lights of the built-in scene; this scene's image is a PNG");
  if (s.params.motion.on() && glow_image)
    c.error("/glow/motion", "moves the lights of the scene image; the glow image would not follow");
  // Only the glow's own extract draws the rendering context.
  if (s.effect != EffectKind::Glow && glow_image)
    c.error("/glow_image",
            fmt::format("applies to effect \"glow\" only, not \"{}\"", effect_name(s.effect)),
            true);
  if (s.effect != EffectKind::Glow && glow && member(*glow, "fog"))
    c.error("/glow/fog",
            fmt::format("applies to effect \"glow\" only, not \"{}\"", effect_name(s.effect)),
            true);
  std::vector<std::string> context_warns = std::move(s.warnings);
  s.warnings = effect_warnings(s);
  // With a glow render the scene image's alpha says nothing about what glows.
  if (!glow_image) s.warnings.insert(s.warnings.end(), image_warns.begin(), image_warns.end());
  s.warnings.insert(s.warnings.end(), context_warns.begin(), context_warns.end());
}

// Everything up to the validated scene; diagnostics left in `c`.
std::optional<Scene> parse(std::string_view text, const std::string& file_name,
                           const std::string& base_dir, FieldChecker& c, JsonLocations& where) {
  if (text.size() > kMaxSceneBytes) {
    c.error_at(0, 0,
               fmt::format("the scene is {} bytes; a scene may have at most {}", text.size(),
                           kMaxSceneBytes));
    return std::nullopt;
  }
  if (auto deep = nesting_beyond(text, kMaxNesting)) {
    c.error_at(*deep, 1, fmt::format("nested deeper than {} levels", kMaxNesting));
    return std::nullopt;
  }
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& e) {
    c.error_at(e.byte > 0 ? e.byte - 1 : 0, 1, syntax_message(e));
    return std::nullopt;
  } catch (const Json::exception& e) { // a number beyond the range of a double
    where = locate_json(text);
    const TextSpan s = where.number_overflow.value_or(TextSpan{});
    c.error_at(s.offset, s.length,
               where.number_overflow ? "number out of the range of a double" : e.what());
    return std::nullopt;
  }
  where = locate_json(text);
  for (const auto& [pointer, key] : where.duplicate_keys)
    c.error_at(key.offset, key.length, fmt::format("{}: duplicate key", pointer));
  Scene s;
  s.file = file_name;
  read_scene(j, base_dir, c, s);
  if (c.failed()) return std::nullopt;
  return s;
}

} // namespace

std::span<const std::string_view> scene_keys() {
  return kSceneKeys;
}

std::string resolve_path(const std::string& base_dir, const std::string& path) {
  namespace fs = std::filesystem;
  if (base_dir.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(base_dir) / path).lexically_normal().string();
}

ir::Result<Scene> parse_scene(std::string_view json_text, const std::string& file_name,
                              const std::string& base_dir) {
  ir::SourceManager sm;
  const uint32_t file = sm.add(file_name, std::string(json_text));
  JsonLocations where;
  FieldChecker check(sm.files[file].text, file, where);
  std::optional<Scene> scene;
  try {
    scene = parse(sm.files[file].text, file_name, base_dir, check, where);
  } catch (const std::exception& e) { // not expected; never let it escape
    check.error_at(0, 0, fmt::format("internal error while reading the scene: {}", e.what()));
  }
  if (check.failed() || !scene) {
    ir::DiagnosticSink sink;
    check.move_to(sink);
    return ir::fail_rendered(file_name, std::string(kSceneRule), ir::render_text(sink, sm));
  }
  return std::move(*scene);
}

} // namespace tierlift::effects
