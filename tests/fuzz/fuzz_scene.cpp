// Feeds arbitrary bytes to the scene loader as a scene file's JSON text (relative paths
// resolve against listings/scenes, so a mutated seed can still name sign.png and the
// listings). Any crash, hang, escaped exception or sanitizer report is a finding, and so is
// a rejection without a file:line:col diagnostic or an accepted scene outside its limits.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "tierlift/effects/scenes/scene.h"

using namespace tierlift;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ir::Result<effects::Scene> r = effects::parse_scene(
      text, "fuzz.json", std::string(TIERLIFT_SOURCE_DIR) + "/listings/scenes");
  if (!r) {
    // Compiler form: "fuzz.json:LINE:COL: error: …" (or the named PNG's own error).
    if (r.message().empty() || r.message().find("error: ") == std::string::npos) std::abort();
    return 0;
  }
  const effects::EffectParams& p = r->params;
  if (p.width == 0 || p.height == 0 || p.downsample < 1 || p.downsample > 4) std::abort();
  return 0;
}
