// `tierlift glow --frames N` on a moving scene: what it prints of the frames run_scene ran
// and compared (effects::Animation).
#pragma once

#include <nlohmann/json.hpp>

#include "glow_report.h"
#include "tierlift/effects/scenes/scene_run.h"

namespace tierlift::cli {

void print_animation(const effects::Animation& a);
nlohmann::json animation_json(const effects::Animation& a);

} // namespace tierlift::cli
