// Two devices' runs of the same graph compared pass by pass (each pass's target right
// after it) and for the final frame, judged against design.md's agreement targets for the
// target's format (img::judge).
#pragma once

#include <string>
#include <vector>

#include "tierlift/effects/run_graph.h"
#include "tierlift/image/compare.h"

namespace tierlift::effects {

struct PassAgreement {
  std::string pass, target;
  img::Comparison comparison;
  img::Verdict verdict;
};

struct RunAgreement {
  std::vector<PassAgreement> passes; // one row per pass, then one row "frame" (`frame`)
  bool all_pass = false;
  std::string error; // runs that cannot be compared (different pass lists, sizes)
};

// `a` and `b` must come from run_graph(..., keep_pass_images = true) on the same graph.
// `frame` names the texture compared as the final frame (from the two image maps).
RunAgreement compare_runs(const GraphRun& a, const ImageMap& a_images, const GraphRun& b,
                          const ImageMap& b_images, const std::string& frame);

} // namespace tierlift::effects
