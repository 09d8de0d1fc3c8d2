// Glow scenes: the scene image (the built-in neon scene or a PNG with alpha), its size and
// the glow parameters, read from a JSON file (schema: listings/scenes/README.md and
// listings/scenes/scene.schema.json). Loading validates everything; every problem becomes
// a compiler-style diagnostic naming the field by its JSON pointer:
//   scene.json:4:19: error: /glow/downsample: 9 is outside 1..4
//       "downsample": 9,
//                     ^
// No exception escapes on bad input.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/effects/glow/glow.h"
#include "tierlift/effects/glow/glsl_blur.h"
#include "tierlift/effects/glow/outline.h"
#include "tierlift/effects/glow/radial.h"
#include "tierlift/image/io.h"
#include "tierlift/ir/result_diagnostics.h"

namespace tierlift::effects {

inline constexpr std::string_view kBuiltinNeon = "builtin:neon";

// The effects a scene may run: a closed set, so every dispatch on it is a switch the
// compiler checks for a missing case. Their names and the scene key of each one's own
// parameters are in one registry (effect_kinds(), scene_effect.cpp).
enum class EffectKind : uint8_t { Glow, RadialBeams, StencilOutline, GlslBlur };

struct EffectInfo {
  EffectKind kind;
  std::string_view name;   // the scene's "effect" value, e.g. "radial-beams"
  std::string_view object; // the key of its own parameters ("radial"); empty: none
};

// Every effect, in the order the schema and the messages list them.
std::span<const EffectInfo> effect_kinds();
// The registry's entry of `kind`, its name, and the kind named `name` (none: not an effect).
const EffectInfo& effect_info(EffectKind kind);
inline std::string_view effect_name(EffectKind kind) {
  return effect_info(kind).name;
}
std::optional<EffectKind> parse_effect_kind(std::string_view name);

struct Scene {
  std::string file;    // the JSON file it came from ("" for the built-in default or --image)
  std::string image;   // "builtin:neon" (make_default_scene) or a resolved PNG path
  EffectParams params; // width/height = the image's size; tier, downsample, format, half_texel,
                       // profile, intensity, listing_files
  // Which effect runs: Glow ("glow"), the default; RadialBeams ("radial-beams", its
  // parameters in `radial`; tier, format and listings from `params`); StencilOutline
  // ("stencil-outline", `outline`; the glow parameters serve it: size, blur profile,
  // intensity, format); GlslBlur ("glsl-blur", `glsl`).
  EffectKind effect = EffectKind::Glow;
  RadialParams radial;   // "radial": {…} for "radial-beams"
  OutlineParams outline; // "outline": {…} for "stencil-outline"
  GlslBlurParams glsl;   // "glsl": {…} for "glsl-blur" (paths relative to the scene's folder)
  // One line each, without a "warning:" prefix: glow_warnings(params) (the CLI prints those
  // itself) followed by what only the image shows (an alpha that is 1 or 0 everywhere).
  std::vector<std::string> warnings;
};

// The scene changes from frame to frame: the glow's after-image, keyframes or motion
// (EffectParams::animated), or a radial-beams star that moves. `--frames N` then runs and
// compares N different frames.
bool scene_animated(const Scene& scene);

// The graph the scene's effect builds: build_glow, build_radial, build_outline or
// build_glsl_blur.
PlanResult build_scene_effect(const Scene& scene);
// The warnings of that effect's parameters (glow_warnings or glsl_blur_warnings).
std::vector<std::string> effect_warnings(const Scene& scene);

// A scene that cannot be had fails with one error of rule kSceneIoRule when the file itself
// could not be read (missing, over the cap: the CLI's exit 2), or kSceneRule when it was
// read and is wrong (exit 1). Its message is the rendered diagnostics ("FILE:LINE:COL:
// error: …", the source line and a caret; '\n'-ended), not positions: the scene's text lives
// only inside the loader, so there is no SourceManager left to render them against later.
inline constexpr std::string_view kSceneIoRule = "io";
inline constexpr std::string_view kSceneRule = "scene";

// Reads (within io::kSceneCap; "-" = standard input) and validates a scene file; relative
// paths in it are relative to its folder.
ir::Result<Scene> load_scene_file(const std::string& path);
// The same for text already read: `file_name` is what diagnostics show, `base_dir` the
// folder that relative paths start from ("" = the working directory).
ir::Result<Scene> parse_scene(std::string_view json_text, const std::string& file_name,
                              const std::string& base_dir);

// builtin:neon at 1280×720 with the default glow parameters (EffectParams{}).
Scene default_scene();

// `--image`: a PNG with alpha (alpha marks what glows) and the default glow parameters at
// the PNG's size. Errors: "FILE: error: …".
ir::Result<Scene> scene_from_png(const std::string& png_path);
// What `glow` and `report` draw: the scene file when one is named, else the PNG, else
// default_scene().
ir::Result<Scene> load_scene(const std::string& scene_path, const std::string& png_path);

// The scene image as RGBA32F: the built-in made in code at params' size, or the PNG read
// again (its size must still equal params.width × params.height).
img::ImageResult load_scene_image(const Scene& scene);
// Frame `frame` (from 1) of a moving scene (params.motion: the built-in scene's lights on
// their circles, the angle 2π·(frame − 1)/period); frame 1 is load_scene_image's.
img::ImageResult load_scene_image(const Scene& scene, unsigned frame);

// Every file the scene reads, which no output may replace: the scene file, its image, the
// glow image and the fog's depth image, the listings and GLSL files it names, and what
// those listings #include (their preprocessor run with the scene's listing options). Paths
// as the scene resolved them; "-" and built-in names are left out.
std::vector<std::string> scene_input_files(const Scene& scene);

// What a run with these parameters should be told, one line each; empty when all is well.
// Weights that do not sum to one: "profile weights sum to 0.98: the glow is 3.96 % darker
// than its sources (0.9604 after both axes)" — the blur runs on x, then on y, so the
// glow's brightness is scaled by the square of the sum.
std::vector<std::string> glow_warnings(const EffectParams& params);

// The keys a scene may have at the top level, in "glow" and in "glow/profile" — the loader
// rejects every other key; the schema file lists the same ones (a test keeps them equal).
std::span<const std::string_view> scene_keys();
std::span<const std::string_view> scene_glow_keys();
std::span<const std::string_view> scene_profile_keys();
std::span<const std::string_view> scene_fog_keys();     // "glow/fog"
std::span<const std::string_view> scene_radial_keys();  // "radial"
std::span<const std::string_view> scene_outline_keys(); // "outline"
std::span<const std::string_view> scene_glsl_keys();    // "glsl"
// The values "effect" may take: the names of effect_kinds(), in its order.
std::span<const std::string_view> scene_effects();

} // namespace tierlift::effects
