// The frame-to-frame parts of a scene's "glow" object: ramped numbers ({"keyframes":
// [[frame, value], …]}) and the after-image ({"mode": …, "gain": …}).
#include <fmt/format.h>

#include "scene_parts.h"

namespace tierlift::effects {
namespace {

constexpr std::string_view kRampKeys[] = {"keyframes"};
constexpr std::string_view kAfterimageKeys[] = {"mode", "gain"};
constexpr std::string_view kMotionKeys[] = {"radius", "period"};
constexpr unsigned kMaxKeyframe = 100000; // the most frames --frames runs

// [[frame, value], …]: frames 1..kMaxKeyframe, strictly increasing; values in `range`.
void read_keyframes(const Json& v, const std::string& at, FieldChecker& c, NumberRange range,
                    Keyframes& out) {
  if (!v.is_array() || v.empty()) {
    c.error(at, fmt::format("{} is not a non-empty array; expected [[frame, value], …]",
                            FieldChecker::shown(v)));
    return;
  }
  for (size_t i = 0; i < v.size(); ++i) {
    const std::string item = fmt::format("{}/{}", at, i);
    if (!v[i].is_array() || v[i].size() != 2) {
      c.error(item, fmt::format("{} is not a pair [frame, value]", FieldChecker::shown(v[i])));
      continue;
    }
    const std::optional<int64_t> frame = c.integer(v[i][0], item + "/0", 1, kMaxKeyframe);
    const std::optional<double> value = c.number(v[i][1], item + "/1", range);
    if (!frame || !value) continue;
    if (!out.points.empty() && unsigned(*frame) <= out.points.back().first) {
      c.error(item + "/0", fmt::format("frame {} does not come after frame {}: keyframes are "
                                       "listed in increasing frame order",
                                       *frame, out.points.back().first));
      continue;
    }
    out.points.emplace_back(unsigned(*frame), *value);
  }
}

} // namespace

void read_ramped(const Json& v, const std::string& at, FieldChecker& c, NumberRange range,
                 double& constant, Keyframes& ramp) {
  if (v.is_object()) {
    if (!c.object(v, at, kRampKeys, kRampKeys)) return;
    if (const Json* k = member(v, "keyframes"))
      read_keyframes(*k, at + "/keyframes", c, range, ramp);
    if (!ramp.empty()) constant = ramp.points.front().second;
    return;
  }
  if (!v.is_number()) {
    c.error(at, fmt::format("{} is neither a number nor {{\"keyframes\": [[frame, value], …]}}",
                            FieldChecker::shown(v)));
    return;
  }
  if (auto x = c.number(v, at, range)) constant = *x;
}

void read_afterimage(const Json& v, const std::string& at, FieldChecker& c, EffectParams& p) {
  if (!c.object(v, at, kAfterimageKeys, std::span<const std::string_view>(kAfterimageKeys, 1)))
    return;
  const Json* mode_json = member(v, "mode");
  if (auto mode = mode_json ? c.string(*mode_json, at + "/mode") : std::nullopt) {
    if (*mode == "sources")
      p.afterimage = Afterimage::Sources;
    else if (*mode == "glow")
      p.afterimage = Afterimage::Glow;
    else if (*mode != "off")
      c.error(at + "/mode", fmt::format("{} is not an after-image; expected \"sources\", "
                                        "\"glow\" or \"off\"",
                                        FieldChecker::shown(*mode_json)));
  }
  if (const Json* gain = member(v, "gain"))
    read_ramped(*gain, at + "/gain", c, NumberRange{0, 4}, p.afterimage_gain,
                p.afterimage_gain_ramp);
}

void read_motion(const Json& v, const std::string& at, FieldChecker& c, EffectParams& p) {
  if (!c.object(v, at, kMotionKeys, kMotionKeys)) return;
  if (const Json* radius = member(v, "radius"))
    if (auto r = c.number(*radius, at + "/radius", NumberRange{0, 0.5})) p.motion.radius = *r;
  if (const Json* period = member(v, "period"))
    if (auto n = c.integer(*period, at + "/period", 1, kMaxKeyframe))
      p.motion.period = unsigned(*n);
}

} // namespace tierlift::effects
