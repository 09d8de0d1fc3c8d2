// The pieces of scene loading shared between its files (scene_parse.cpp reads the top level
// and the image, scene_glow.cpp the "glow" object, scene.cpp the rest of scene.h).
#pragma once

#include <string>
#include <vector>

#include "scene_check.h"
#include "tierlift/effects/glow/glow.h"
#include "tierlift/effects/glow/glsl_blur.h"
#include "tierlift/effects/glow/radial.h"
#include "tierlift/effects/scenes/scene.h"
#include "tierlift/image/image.h"

namespace tierlift::effects {

// "/glow": every field into `params` (what is absent keeps its default).
void read_glow(const Json& glow, FieldChecker& check, const std::string& base_dir,
               EffectParams& params);

// "/radial": every field into `radial` (what is absent keeps its default); its "tier" goes
// to glow.tier, which also decides the strength's limit (ps.1.x constants).
void read_radial(const Json& radial, FieldChecker& check, EffectParams& glow, RadialParams& out);
// "/outline": the polygon, its two colours and the stencil reference.
void read_outline(const Json& outline, FieldChecker& check, OutlineParams& out);
// "/effect" and that effect's own object ("/radial", "/outline", "/glsl"); an effect's object
// without the effect that reads it is an error at the object's key (scene_effect.cpp).
void read_effect(const Json& scene, FieldChecker& check, const std::string& base_dir, Scene& out);
// "/glsl": the glsl-blur effect's fields into `glsl` (scene_glsl.cpp).
void read_glsl(const Json& glsl, FieldChecker& check, const std::string& base_dir,
               GlslBlurParams& params);
// A number or {"keyframes": [[frame, value], …]} (scene_frames.cpp): the number into
// `constant`, or the keyframes into `ramp` and the first value into `constant`. Frames
// 1..100000, strictly increasing; every value in `range`.
void read_ramped(const Json& v, const std::string& pointer, FieldChecker& check, NumberRange range,
                 double& constant, Keyframes& ramp);
// "/glow/afterimage": {"mode": "sources" | "glow" | "off", "gain": ramped 0..4}.
void read_afterimage(const Json& v, const std::string& pointer, FieldChecker& check,
                     EffectParams& params);

// "/glow/motion": {"radius": 0..0.5 scene heights, "period": 1..100000 frames}, both needed.
void read_motion(const Json& v, const std::string& pointer, FieldChecker& check,
                 EffectParams& params);

// "/glow_image" and "/glow/fog" (scene_context.cpp): the glow render and the glow fog, their
// images read and checked against the scene's size (params.width/height, known by then).
void read_glow_image(const Json& v, FieldChecker& check, const std::string& base_dir, Scene& out);
void read_fog(const Json& v, const std::string& pointer, FieldChecker& check,
              const std::string& base_dir, EffectParams& params);

// `path` as seen from `base_dir` ("" = the working directory); absolute paths stay.
std::string resolve_path(const std::string& base_dir, const std::string& path);

// What a scene image's alpha says that its maker may not have meant.
std::vector<std::string> image_warnings(const img::Image& image);

} // namespace tierlift::effects
