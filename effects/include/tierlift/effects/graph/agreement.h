// Two devices' runs of the same graph compared pass by pass (each pass's target right
// after it) and for the final frame, judged against docs/design.md's agreement targets for the
// target's format (img::judge), with RGBA8 rounding midpoints counted as agreeing.
#pragma once

#include <string>
#include <vector>

#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/image/compare.h"

namespace tierlift::effects {

struct PassAgreement {
  std::string pass, target;
  img::Comparison comparison; // the plain comparison (identical means bit for bit)
  // RGBA8: pixels that differ by one step where one run's device proved a rounding tie
  // (PassDevice::rounding_midpoints, at most one step whatever the mask holds). The verdict
  // counts them as identical, in the identical share and in the max abs; midpoint_share is
  // their share of the pixels (the "slack used" figure of the glow table).
  uint64_t midpoint_pixels = 0;
  double midpoint_share = 0;
  double identical_share_with_midpoints = 1;
  img::Verdict verdict;
};

struct RunAgreement {
  std::vector<PassAgreement> passes; // one row per pass, then one row "frame" (`frame`)
  bool all_pass = false;
};

// `a` and `b` must come from run_graph(..., keep_pass_images = true) on the same graph.
// `frame` names the texture compared as the final frame (from the two image maps). Runs
// that cannot be compared (different pass lists, image sizes, no frame) fail (rule
// "agreement"); a comparison that finds differences is a success whose rows say so.
ir::Result<RunAgreement> compare_runs(const GraphRun& a, const ImageMap& a_images,
                                      const GraphRun& b, const ImageMap& b_images,
                                      const std::string& frame);

} // namespace tierlift::effects
