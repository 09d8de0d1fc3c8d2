// The dx7 glow tier (glow.h): no shaders. The blur is a stack of full-screen quads drawn
// with two fixed-function texture stages (dx7/blur_pair.tss, or the file a scene names in
// its place), lowered into the IR the other tiers use, so every device runs it as it runs a
// listing. The helper passes are the dx8 tier's ps.1.x listings. The graph itself is built
// by glow_common.cpp.
#include <fmt/format.h>

#include "glow_common.h"
#include "tierlift/io/bounded_read.h"
#include "tierlift/listings/embedded.h"

namespace tierlift::effects {
namespace {

ir::Result<std::shared_ptr<const tss::Lowered>> blur_states(const EffectParams& p) {
  std::string text, name;
  if (auto it = p.listing_files.find(kDx7BlurStates); it != p.listing_files.end()) {
    ir::Result<std::string> read = io::read_bounded(it->second, io::kListingCap);
    if (!read) {
      std::string why = read.message();
      const std::string head = it->second + ": ";
      if (why.starts_with(head)) why.erase(0, head.size());
      return ir::fail(it->second, "io",
                      fmt::format("{}: error: {} (it replaces built-in '{}')", it->second, why,
                                  kDx7BlurStates));
    }
    text = std::move(*read);
    if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
    name = it->second;
  } else {
    std::optional<std::string_view> builtin = listings::find_embedded(kDx7BlurStates);
    if (!builtin)
      return ir::fail(std::string(kDx7BlurStates), "tss",
                      fmt::format("no built-in stage states '{}'", kDx7BlurStates));
    text = std::string(*builtin);
    name = std::string(kDx7BlurStates);
  }
  ir::Result<tss::Lowered> lowered = tss::load_stage_states(std::move(text), name);
  if (!lowered) return std::move(lowered).failure();
  if (lowered->texture_stages == 0)
    return ir::fail(name, "tss",
                    fmt::format("{}: error: no stage reads its texture: a blur quad would sample "
                                "nothing\n",
                                name));
  return std::make_shared<const tss::Lowered>(std::move(*lowered));
}

} // namespace

PlanResult build_glow_dx7(const EffectParams& params) {
  ir::Result<std::shared_ptr<const tss::Lowered>> blur = blur_states(params);
  if (!blur) return plan_failure(blur.message());
  std::shared_ptr<const tss::Lowered> states = std::move(blur).value();
  // As tier dx8 (glow_dx8.cpp): above 1, c0 = value / 4 and the listing's _x4. Only the
  // helper listings (no blur listings): the blur comes from the stage states. An 8-bit
  // colour holds at most 1 as well, as a ps.1.x constant does.
  detail::TierRecipe r = detail::ps1x_recipe(params);
  r.tier = "dx7";
  r.taps_per_blur_pass = kTapsPerBlurPassDx7;
  r.why_limit = "the helper passes are the dx8 tier's ps.1.x listings";
  r.stage_blur = std::move(states);
  r.rounding = params.weight_rounding;
  // Direct3D 7 saturates each stage's result to [0, 1]: the ps.1.x clamp at 1 is that for
  // the blur's non-negative values (glow.h).
  EffectParams p = params;
  p.ps1x_max = 1;
  return detail::build_glow_graph(p, r);
}

} // namespace tierlift::effects
