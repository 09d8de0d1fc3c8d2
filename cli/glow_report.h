// What `tierlift glow` prints and writes once the scene has run (effects::run_scene): the
// agreement table (per pass and for the frame, every pair of ways), its JSON form, and the
// image files.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tierlift/effects/glow/prune.h"
#include "tierlift/effects/scenes/scene_run.h"
#include "tierlift/io/output_folder.h"
#include "tierlift/ir/result.h"

namespace tierlift::cli {

// The table: one row per pass and one for the frame; for each pair max abs, RMSE and the
// share of identical pixels, a '!' after a pair beyond docs/design.md's targets.
void print_agreement_table(const std::vector<effects::PairAgreement>& pairs);
nlohmann::json agreement_json(const std::vector<effects::PairAgreement>& pairs);

// "frames: setup, then N frames each" and one row per device: setup, median, min, max ms.
void print_frames_table(const std::vector<effects::FrameReport>& frames);
// {"<device>": {"setup_ms", "median_ms", "min_ms", "max_ms", "n"}}
nlohmann::json frames_json(const std::vector<effects::FrameReport>& frames);

// Writes {scene,glow,final}-<way>.png for each way into `out` (opaque copies: the scene's
// alpha is the glow mask, and viewers would show the ground as transparent), plus .pfm of
// each when the target format is a float format. Empty string on success. The folder
// refuses a name that is one of the run's inputs before anything is written; nothing
// reaches DIR before out.commit().
std::string write_glow_images(io::OutputFolder& out, const std::vector<effects::WayRun>& ways,
                              bool float_targets);

// What pruning left out, limited to a box and kept: `glow --explain` prints it (`varies`: the
// scene changes per frame, so the whole plan ran); --json carries it as result.pruning.
void print_pruning(const effects::PrunedGraph& pruned, bool no_prune, bool varies);
nlohmann::json pruning_json(const effects::PrunedGraph& pruned, bool enabled);

} // namespace tierlift::cli
