// `tierlift run`'s flags into a pass::RunRequest (run_request.h).
#include "run_request.h"

#include <cmath>

#include <fmt/format.h>

#include "run_depth.h"
#include "run_flags.h"
#include "tierlift/image/image.h"

namespace tierlift::cli {
namespace {

// A usage problem: reported under rule "usage", exit 2.
ir::Failure usage_error(std::string message) {
  return ir::fail("run", "usage", std::move(message));
}

// Sets `out` from a parsed flag value; false, with the first usage error kept in `error`.
template <class T, class U>
bool take(ir::Result<T> value, U& out, std::optional<ir::Failure>& error) {
  if (!value) {
    if (!error) error = std::move(value).failure();
    return false;
  }
  out = std::move(value).value();
  return true;
}
template <class T, class U>
bool take(std::optional<T> value, std::string message, U& out, std::optional<ir::Failure>& error) {
  if (value) return take(ir::Result<T>(std::move(*value)), out, error);
  if (!error) error = usage_error(std::move(message));
  return false;
}

// The --input, --attr, --texture, --bump and --probe settings into `r` (the size known).
void read_settings(const RunFlags& f, pass::RunRequest& r, std::optional<ir::Failure>& error) {
  for (const auto& s : f.inputs) take(parse_input_setting(s), r.inputs.emplace_back(), error);
  for (const auto& s : f.attrs) take(parse_attr_setting(s), r.attrs.emplace_back(), error);
  for (const auto& s : f.textures) take(parse_texture_setting(s), r.textures.emplace_back(), error);
  for (const auto& s : f.bumps) take(parse_bump_setting(s), r.bump_matrices.emplace_back(), error);
  for (const auto& s : f.probes) {
    pass::ProbePoint& p = r.probes.emplace_back();
    if (take(parse_probe(s), p, error) && (p.x >= r.width || p.y >= r.height) && !error)
      error = usage_error(fmt::format("--probe {}: outside the {}x{} image", s, r.width, r.height));
  }
}

} // namespace

// Every flag but --const (read once the listings' constant tables are known); the first
// flag in error, in the order below, is the one reported.
ir::Result<pass::RunRequest> build_request(const RunFlags& f) {
  pass::RunRequest r;
  std::optional<ir::Failure> error;
  std::array<uint32_t, 2> size{};
  if (take(parse_size(f.size), size, error)) {
    r.width = size[0];
    r.height = size[1];
  }
  take(img::parse_format(f.format),
       fmt::format("--format '{}': expected rgba8, rgba16f or rgba32f", f.format), r.format, error);
  if (!error) read_settings(f, r, error);
  take(parse_filter(f.filter), fmt::format("--filter '{}': expected point or linear", f.filter),
       r.filter, error);
  take(parse_address(f.address),
       fmt::format("--address '{}': expected clamp, wrap, mirror or border", f.address), r.address,
       error);
  take(parse_pixel_center(f.pixel_center),
       fmt::format("--pixel-center '{}': expected d3d9 or modern", f.pixel_center),
       r.conventions.pixel_center, error);
  if ((f.front_face != "cw" && f.front_face != "ccw") && !error)
    error = usage_error(fmt::format("--front-face '{}': expected cw or ccw", f.front_face));
  r.front_face =
      f.front_face == "ccw" ? pass::FrontFace::CounterClockwise : pass::FrontFace::Clockwise;
  if ((f.subtexel_bits < 0 || f.subtexel_bits > 24) && !error)
    error =
        usage_error(fmt::format("--subtexel-bits {}: expected 0 (exact) .. 24", f.subtexel_bits));
  r.conventions.subtexel_bits = f.subtexel_bits;
  const ir::Result<float> ps1x_max = ir::parse_ps1x_max(f.ps1x_max);
  if (!ps1x_max && !error) error = usage_error("--ps1x-max " + ps1x_max.message());
  // --outputN draws oCN into a further render target, so oC1..oC(N−1) must be asked for too.
  for (size_t i = 0; i < f.more_outputs.size(); ++i) {
    if (f.more_outputs[i].empty()) continue;
    if (r.color_targets != i + 1 && !error)
      error = usage_error(fmt::format("--output{} needs --output{} too (render targets are drawn "
                                      "in order, oC1 first)",
                                      i + 1, r.color_targets));
    r.color_targets = static_cast<uint32_t>(i + 2);
  }
  if (error) return std::move(*error);
  r.conventions.ps1x_max_value = *ps1x_max;
  if (f.mips == "auto") {
    r.generated_levels = 0;
  } else {
    const std::optional<uint32_t> n = parse_level_count(f.mips);
    if (!n) return usage_error(fmt::format("--mips '{}': expected auto or 1..32 levels", f.mips));
    r.generated_levels = *n;
  }
  const std::optional<pass::MipFilter> mf = parse_mip_filter(f.mip_filter);
  if (!mf)
    return usage_error(
        fmt::format("--mip-filter '{}': expected none, point or linear", f.mip_filter));
  if (f.max_mip_level < 0 || f.max_mip_level > 31)
    return usage_error(fmt::format("--max-mip-level {}: expected 0..31", f.max_mip_level));
  if (!std::isfinite(f.lod_bias))
    return usage_error(fmt::format("--lod-bias {}: expected a finite number", f.lod_bias));
  r.mip = {*mf, f.lod_bias, static_cast<uint32_t>(f.max_mip_level)};
  r.threads = f.threads;
  r.srgb_texture = f.srgb_texture;
  r.srgb_write = f.srgb_write;
  r.texcoords_from_quad = true; // a t# --input does not set is the quad's uv, as in glow
  ir::Result<pass::DepthStencilState> depth = depth_state(f);
  if (!depth) return std::move(depth).failure();
  r.depth_stencil = *depth;
  return r;
}

} // namespace tierlift::cli
