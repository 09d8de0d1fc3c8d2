// tierlift diff A B: how far two images are apart (img::diff_images): max abs, RMSE, the
// share of pixels off by more than K/255, the worst pixels, an optional heat map; exit 1
// beyond the tolerance. Only flags and printing live here.
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "commands.h"
#include "front_end.h"
#include "report.h"
#include "tierlift/image/builtin.h"
#include "tierlift/image/diff.h"
#include "tierlift/image/io.h"

namespace tierlift::cli {
namespace {

struct DiffFlags {
  std::string a, b, heatmap;
  double off_by = 1;
  size_t worst = 5;
  std::optional<double> tolerance, max_off_share;
  bool json = false;
};

std::string rgba_text(const std::array<float, 4>& v) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g}, {:.6g})", v[0], v[1], v[2], v[3]);
}

// A number JSON can hold: an infinite difference (a NaN or inf in one image only) is null.
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

nlohmann::json result_json(const DiffFlags& f, const img::Diff& d, const img::DiffLimits& limits,
                           const img::Verdict& verdict) {
  const img::Comparison& c = d.comparison;
  nlohmann::json worst = nlohmann::json::array();
  for (const img::PixelDifference& p : d.worst)
    worst.push_back({{"x", p.x},
                     {"y", p.y},
                     {"a", {number(p.a[0]), number(p.a[1]), number(p.a[2]), number(p.a[3])}},
                     {"b", {number(p.b[0]), number(p.b[1]), number(p.b[2]), number(p.b[3])}},
                     {"difference", number(p.difference)},
                     {"channel", std::string(1, "RGBA"[p.channel])}});
  nlohmann::json per_channel = nlohmann::json::array(), rmse = nlohmann::json::array();
  for (int ch = 0; ch < 4; ++ch) {
    per_channel.push_back(number(c.max_abs[ch]));
    rmse.push_back(number(c.rmse[ch]));
  }
  return {{"a", f.a},
          {"b", f.b},
          {"size", {{"width", c.width}, {"height", c.height}}},
          {"max_abs", number(c.max_abs_all)},
          {"max_abs_per_channel", per_channel},
          {"rmse", number(c.rmse_all)},
          {"rmse_per_channel", rmse},
          {"identical_share", c.identical_share},
          {"off_by", d.off_steps},
          {"off_pixels", d.off_pixels},
          {"off_share", d.off_share},
          {"worst", worst},
          {"tolerance",
           {{"max_abs", limits.max_abs ? nlohmann::json(*limits.max_abs) : nlohmann::json()},
            {"max_off_share",
             limits.max_off_share ? nlohmann::json(*limits.max_off_share) : nlohmann::json()}}},
          {"within_tolerance", verdict.pass},
          {"heatmap", f.heatmap.empty() ? nlohmann::json() : nlohmann::json(f.heatmap)}};
}

void print_text(const DiffFlags& f, const img::Diff& d, const img::Verdict& verdict) {
  const img::Comparison& c = d.comparison;
  fmt::print("{} vs {} ({}x{}): {}\n", f.a, f.b, c.width, c.height, img::describe(c));
  fmt::print("off by more than {:g}/255: {} of {} pixels ({:.4f} %)\n", d.off_steps, d.off_pixels,
             c.pixels, 100.0 * d.off_share);
  if (!d.worst.empty()) fmt::print("worst pixels (x,y: A | B, largest difference):\n");
  for (const img::PixelDifference& p : d.worst)
    fmt::print("  {},{}: {} | {}, {:.6g} ({})\n", p.x, p.y, rgba_text(p.a), rgba_text(p.b),
               p.difference, "RGBA"[p.channel]);
  fmt::print("{}\n", verdict.summary);
}

// Empty when the flags make sense, else why not.
std::string check_flags(const DiffFlags& f) {
  if (!(f.off_by >= 0) || !std::isfinite(f.off_by))
    return fmt::format("--off-by {}: expected a number of 8-bit steps >= 0", f.off_by);
  if (f.tolerance && !(*f.tolerance >= 0))
    return fmt::format("--tolerance {}: expected a difference >= 0", *f.tolerance);
  if (f.max_off_share && !(*f.max_off_share >= 0 && *f.max_off_share <= 1))
    return fmt::format("--max-off-share {}: expected a share from 0 to 1", *f.max_off_share);
  return {};
}

int run_diff(const DiffFlags& f) {
  Report report("diff", f.json);
  if (std::string why = check_flags(f); !why.empty()) {
    report.error("usage", why);
    return report.finish(kExitUsage);
  }
  if (!f.heatmap.empty()) {
    // -o - is not offered: the heat map is a file beside the printed figures.
    if (ir::Status out = output_conflict(f.heatmap, {f.a, f.b}); !out || f.heatmap == "-") {
      report.error("io", out ? "--heatmap needs a file name ('-' is not one)" : out.message(),
                   f.heatmap);
      return report.finish(kExitUsage);
    }
  }
  std::optional<img::Image> images[2];
  for (int i = 0; i < 2; ++i) {
    const std::string& path = i == 0 ? f.a : f.b;
    img::ImageResult r = img::load_texture(path);
    if (!r) { // unreadable or not an image: nothing was compared
      report.error(img::is_io_error(r) ? "io" : "image", r.message(), path);
      return report.finish(kExitUsage);
    }
    images[i] = std::move(r).value();
  }
  ir::Result<img::Diff> diff = img::diff_images(*images[0], *images[1], {f.off_by, f.worst});
  if (!diff) { // different sizes: the images differ, which is exit 1 as any difference
    report.error("size", fmt::format("{} vs {}: {}", f.a, f.b, diff.message()));
    return report.finish(kExitInvalid);
  }
  img::DiffLimits limits{f.tolerance, f.max_off_share};
  if (!limits.max_abs && !limits.max_off_share) limits.max_abs = 0.0; // any difference counts
  const img::Verdict verdict = img::judge_diff(*diff, limits);
  if (!f.heatmap.empty()) {
    ir::Status written =
        img::write_png(f.heatmap, img::heat_map(*images[0], *images[1]), img::PngDepth::Bits8);
    if (!written) {
      report.error("io", written.message(), f.heatmap);
      return report.finish(kExitUsage);
    }
  }
  if (report.json())
    report.result() = result_json(f, *diff, limits, verdict);
  else
    print_text(f, *diff, verdict);
  return report.finish(verdict.pass ? kExitOk : kExitInvalid);
}

} // namespace

void register_diff_command(CLI::App& app) {
  auto f = std::make_shared<DiffFlags>();
  CLI::App* sub = app.add_subcommand(
      "diff", "Compare two images (PNG, PFM or builtin:NAME): max abs, RMSE, share of pixels off, "
              "worst pixels, heat map; exit 1 beyond the tolerance");
  sub->add_option("a", f->a, "First image")->required();
  sub->add_option("b", f->b, "Second image")->required();
  sub->add_option("--off-by", f->off_by,
                  "Count pixels whose largest channel difference exceeds K/255")
      ->capture_default_str();
  sub->add_option("--worst", f->worst, "How many of the worst pixels to list")
      ->capture_default_str();
  sub->add_option("--tolerance", f->tolerance,
                  "Largest channel difference allowed (exit 1 beyond; default 0 when neither "
                  "limit is given)");
  sub->add_option("--max-off-share", f->max_off_share,
                  "Largest share (0..1) of pixels off by more than K/255 allowed (exit 1 beyond)");
  sub->add_option("--heatmap", f->heatmap,
                  "Write the difference as a PNG: black none, red → yellow → white up to the "
                  "largest difference, magenta NaN/inf in one image only");
  sub->add_flag("--json", f->json, "One JSON document on standard output");
  set_action(sub, [f] { return run_diff(*f); });
}

} // namespace tierlift::cli
