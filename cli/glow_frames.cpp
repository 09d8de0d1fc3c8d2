#include "glow_frames.h"

#include <fmt/format.h>

namespace tierlift::cli {

void print_animation(const effects::Animation& a) {
  print_frames_table(a.times);
  for (const effects::FramePairAgreement& p : a.pairs)
    fmt::print("frames {} · {}: {}/{} within targets, worst max abs {:.3g} (frame {}), smallest "
               "identical share {:.3f}%{}\n",
               p.a, p.b, p.frames_within, p.frames, p.worst_max_abs, p.worst_frame,
               100 * p.worst_identical, p.first_failure.empty() ? "" : "; " + p.first_failure);
}

nlohmann::json animation_json(const effects::Animation& a) {
  nlohmann::json j = frames_json(a.times);
  nlohmann::json pairs = nlohmann::json::array();
  for (const effects::FramePairAgreement& p : a.pairs)
    pairs.push_back({{"a", p.a},
                     {"b", p.b},
                     {"frames", p.frames},
                     {"frames_within", p.frames_within},
                     {"worst_max_abs", p.worst_max_abs},
                     {"worst_frame", p.worst_frame},
                     {"smallest_identical_share", p.worst_identical}});
  return {{"times", j}, {"agreement", pairs}};
}

} // namespace tierlift::cli
