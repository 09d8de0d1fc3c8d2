// Reads a scene's "glow" object: tier, downsample, profile, taps, intensity, format,
// half_texel, listings. Ranges are those of listings/scenes/README.md.
#include <filesystem>

#include <fmt/format.h>

#include "scene_parts.h"
#include "tierlift/effects/glow/blur_profile.h"
#include "tierlift/effects/scenes/scene.h"
#include "tierlift/listings/embedded.h"

namespace tierlift::effects {
namespace {

constexpr std::string_view kGlowKeys[] = {
    "tier",       "downsample", "profile",         "taps",     "intensity",
    "format",     "half_texel", "listings",        "ps1x_max", "weight_scale",
    "afterimage", "motion",     "weight_rounding", "fog"};
constexpr std::string_view kProfileKeys[] = {"gaussians", "sawtooth"};
constexpr std::string_view kGaussianKeys[] = {"sigma", "weight"};
constexpr std::string_view kSawtoothKeys[] = {"period", "radius", "weight"};

constexpr NumberRange kLength{0, 4096, true}; // σ and period, in full-resolution pixels
constexpr NumberRange kRadius{0, 4096};
constexpr NumberRange kWeight{0, 1000};
constexpr NumberRange kIntensity{0, 1000};

void read_gaussians(const Json& v, const std::string& at, FieldChecker& c, BlurProfile& out) {
  if (!v.is_array()) {
    c.error(at, fmt::format("{} is not an array; expected [{{\"sigma\": …, \"weight\": …}}, …]",
                            FieldChecker::shown(v)));
    return;
  }
  for (size_t i = 0; i < v.size(); ++i) {
    const std::string item = fmt::format("{}/{}", at, i);
    if (!c.object(v[i], item, kGaussianKeys, kGaussianKeys)) continue;
    Gaussian g;
    if (const Json* s = member(v[i], "sigma"))
      g.sigma = c.number(*s, item + "/sigma", kLength).value_or(g.sigma);
    if (const Json* w = member(v[i], "weight"))
      g.weight = c.number(*w, item + "/weight", kWeight).value_or(g.weight);
    out.terms.push_back(g);
  }
}

void read_sawtooth(const Json& v, const std::string& at, FieldChecker& c, BlurProfile& out) {
  if (!c.object(v, at, kSawtoothKeys, kSawtoothKeys)) return;
  Sawtooth s;
  if (const Json* p = member(v, "period"))
    s.period = c.number(*p, at + "/period", kLength).value_or(s.period);
  if (const Json* r = member(v, "radius"))
    s.radius = c.number(*r, at + "/radius", kRadius).value_or(s.radius);
  if (const Json* w = member(v, "weight"))
    s.weight = c.number(*w, at + "/weight", kWeight).value_or(s.weight);
  out.sawtooth = s;
}

// A profile given in the scene replaces the default one entirely.
void read_profile(const Json& v, const std::string& at, FieldChecker& c, BlurProfile& out) {
  if (!c.object(v, at, kProfileKeys)) return;
  const Json* gaussians = member(v, "gaussians");
  const Json* sawtooth = member(v, "sawtooth");
  if (!gaussians && !sawtooth) {
    c.error(at, "needs \"gaussians\", \"sawtooth\" or both");
    return;
  }
  out.terms.clear();
  out.sawtooth.reset();
  if (gaussians) read_gaussians(*gaussians, at + "/gaussians", c, out);
  if (sawtooth) read_sawtooth(*sawtooth, at + "/sawtooth", c, out);
  if (gaussians && gaussians->is_array() && gaussians->empty() && !sawtooth)
    c.error(at + "/gaussians", "is empty: the profile has no term");
}

void read_listings(const Json& v, const std::string& at, const std::string& base_dir,
                   FieldChecker& c, EffectParams& p) {
  if (!v.is_object()) {
    c.error(at, fmt::format("{} is not an object; expected {{\"<built-in listing>\": \"<file>\"}}",
                            FieldChecker::shown(v)));
    return;
  }
  for (const auto& [name, file] : v.items()) {
    const std::string entry = at + "/" + pointer_token(name);
    if (!listings::find_embedded(name)) {
      c.error(
          entry,
          fmt::format("\"{}\" is not a built-in listing (e.g. \"glow/composite_add.psh\")", name),
          true);
      continue;
    }
    const std::optional<std::string> path = c.string(file, entry);
    if (!path) continue;
    const std::string resolved = resolve_path(base_dir, *path);
    std::error_code ec;
    if (path->empty() || !std::filesystem::is_regular_file(resolved, ec)) {
      c.error(entry, fmt::format("no such file: \"{}\"", resolved));
      continue;
    }
    p.listing_files[name] = resolved;
  }
}

// "ps1x_max": a preset name ("geforce3", "radeon8500", "d3d9", "max") or a number >= 1.
void read_ps1x_max(const Json& v, const std::string& at, FieldChecker& c, EffectParams& p) {
  std::string text;
  if (v.is_string()) {
    text = v.get<std::string>();
  } else if (v.is_number()) {
    text = fmt::format("{}", v.get<double>());
  } else {
    c.error(at, fmt::format("{} is not a preset name or a number", FieldChecker::shown(v)));
    return;
  }
  if (ir::Result<float> m = ir::parse_ps1x_max(text))
    p.ps1x_max = *m;
  else
    c.error(at, m.message());
}

} // namespace

std::span<const std::string_view> scene_glow_keys() {
  return kGlowKeys;
}
std::span<const std::string_view> scene_profile_keys() {
  return kProfileKeys;
}

void read_glow(const Json& g, FieldChecker& c, const std::string& base_dir, EffectParams& p) {
  const std::string at = "/glow";
  if (!c.object(g, at, kGlowKeys)) return;
  if (const Json* v = member(g, "tier"))
    if (auto name = c.string(*v, at + "/tier")) {
      if (auto tier = parse_tier(*name))
        p.tier = *tier;
      else
        c.error(at + "/tier",
                fmt::format("{} is not a tier; expected \"dx9\", \"dx8\", \"dx7\" or \"dx9c\"",
                            FieldChecker::shown(*v)));
    }
  if (const Json* v = member(g, "downsample"))
    if (auto n = c.integer(*v, at + "/downsample", 1, 4)) p.downsample = unsigned(*n);
  if (const Json* v = member(g, "profile")) read_profile(*v, at + "/profile", c, p.profile);
  if (const Json* v = member(g, "taps"))
    if (auto n = c.integer(*v, at + "/taps", 1, kMaxBlurTaps)) {
      if (*n % 2 == 0)
        c.error(at + "/taps",
                fmt::format("{} is even; the kernel is centred, so taps must be odd", *n));
      else
        p.profile.max_taps = unsigned(*n);
    }
  if (const Json* v = member(g, "intensity")) {
    // A ps.1.x constant holds at most 1; the dx8 composite reaches 4 with _x4 (glow.h).
    const bool dx8 = p.tier == Tier::Dx8 || p.tier == Tier::Dx7;
    if (dx8 && v->is_number() && v->get<double>() > 4 && v->get<double>() <= kIntensity.hi)
      c.error(at + "/intensity", fmt::format("{} is outside 0..4, the range of tier {}",
                                             FieldChecker::shown(*v), tier_name(p.tier)));
    else
      read_ramped(*v, at + "/intensity", c, dx8 ? NumberRange{0, 4} : kIntensity, p.intensity,
                  p.intensity_ramp);
  }
  if (const Json* v = member(g, "weight_scale"))
    read_ramped(*v, at + "/weight_scale", c, NumberRange{0, 1000}, p.weight_scale,
                p.weight_scale_ramp);
  if (const Json* v = member(g, "afterimage")) read_afterimage(*v, at + "/afterimage", c, p);
  if (const Json* v = member(g, "motion")) read_motion(*v, at + "/motion", c, p);
  if (const Json* v = member(g, "format"))
    if (auto name = c.string(*v, at + "/format")) {
      if (auto f = img::parse_format(*name))
        p.format = *f;
      else
        c.error(at + "/format",
                fmt::format("{} is not a format; expected \"rgba8\", \"rgba16f\" or \"rgba32f\"",
                            FieldChecker::shown(*v)));
    }
  if (const Json* v = member(g, "half_texel"))
    if (auto b = c.boolean(*v, at + "/half_texel")) p.half_texel = *b;
  if (const Json* v = member(g, "listings")) read_listings(*v, at + "/listings", base_dir, c, p);
  if (const Json* v = member(g, "ps1x_max")) read_ps1x_max(*v, at + "/ps1x_max", c, p);
  if (const Json* v = member(g, "fog")) read_fog(*v, at + "/fog", c, base_dir, p);
  if (const Json* v = member(g, "weight_rounding"))
    if (auto name = c.string(*v, at + "/weight_rounding")) {
      if (auto r = parse_weight_rounding(*name))
        p.weight_rounding = *r;
      else
        c.error(at + "/weight_rounding",
                fmt::format("{} is not a weight rounding; expected \"plain\" or \"error-carry\"",
                            FieldChecker::shown(*v)));
      if (p.tier != Tier::Dx7)
        c.error(at + "/weight_rounding",
                "weight_rounding applies to tier dx7 only (the shader tiers keep float weights)");
    }

  // What only the fields together say: the kernel's radius at this downsample factor.
  if (c.failed()) return;
  if (ir::Result<std::vector<BlurTap>> taps = sample_blur_profile(p.profile, p.downsample); !taps)
    c.error(member(g, "profile") ? at + "/profile" : at, taps.message());
}

} // namespace tierlift::effects
