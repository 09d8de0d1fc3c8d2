// `tierlift diff`'s figures on top of img::compare: off share, worst pixels, heat map.
#include "tierlift/image/diff.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace tierlift::img {
namespace {

// The largest channel difference of pixel p and its channel.
std::pair<double, int> pixel_difference(const Image& a, const Image& b, size_t p) {
  double worst = 0;
  int channel = 0;
  for (int c = 0; c < 4; ++c) {
    const double d = channel_difference(a.rgba[4 * p + c], b.rgba[4 * p + c]);
    if (d > worst) worst = d, channel = c;
  }
  return {worst, channel};
}

// Larger difference first; equal ones in row-major order.
bool worse(const PixelDifference& l, const PixelDifference& r) {
  if (l.difference != r.difference) return l.difference > r.difference;
  return l.y != r.y ? l.y < r.y : l.x < r.x;
}

PixelDifference describe_pixel(const Image& a, const Image& b, size_t p, double d, int channel) {
  PixelDifference out;
  out.x = static_cast<uint32_t>(p % a.width);
  out.y = static_cast<uint32_t>(p / a.width);
  std::copy_n(a.rgba.begin() + 4 * p, 4, out.a.begin());
  std::copy_n(b.rgba.begin() + 4 * p, 4, out.b.begin());
  out.difference = d;
  out.channel = channel;
  return out;
}

// Black → red → yellow → white over t in [0, 1], in thirds.
std::array<float, 4> heat_colour(double t) {
  t = std::clamp(t, 0.0, 1.0) * 3.0;
  const auto part = [&](double from) { return static_cast<float>(std::clamp(t - from, 0.0, 1.0)); };
  return {part(0), part(1), part(2), 1.0f};
}

} // namespace

ir::Result<Diff> diff_images(const Image& a, const Image& b, const DiffOptions& options) {
  ir::Result<Comparison> compared = compare(a, b);
  if (!compared) return std::move(compared).failure();
  Diff out;
  out.comparison = *compared;
  out.off_steps = options.off_steps;
  // The float noise judge() allows: two stored k/255 values differ by up to ~1.5e-5
  // relative more than their step count says.
  const double off_limit = options.off_steps / 255.0 * (1.0 + 1e-4);
  const size_t pixels = size_t{a.width} * a.height;
  for (size_t p = 0; p < pixels; ++p) {
    const auto [d, channel] = pixel_difference(a, b, p);
    if (d > off_limit) ++out.off_pixels;
    if (d == 0 || options.worst_count == 0) continue;
    // Keep the list sorted and at most worst_count long: a heap would do fewer compares,
    // but the list is short (a handful of pixels for a person to read).
    PixelDifference candidate{
        static_cast<uint32_t>(p % a.width), static_cast<uint32_t>(p / a.width), {}, {}, d, channel};
    if (out.worst.size() == options.worst_count && !worse(candidate, out.worst.back())) continue;
    candidate = describe_pixel(a, b, p, d, channel);
    out.worst.insert(std::upper_bound(out.worst.begin(), out.worst.end(), candidate, worse),
                     candidate);
    if (out.worst.size() > options.worst_count) out.worst.pop_back();
  }
  out.off_share = pixels ? static_cast<double>(out.off_pixels) / static_cast<double>(pixels) : 0;
  return out;
}

Verdict judge_diff(const Diff& d, const DiffLimits& limits) {
  Verdict v;
  v.pass = true;
  std::vector<std::string> parts;
  if (limits.max_abs) {
    const bool ok = d.comparison.max_abs_all <= *limits.max_abs;
    v.pass = v.pass && ok;
    parts.push_back(fmt::format("max abs {:.6g} {} {:.6g}", d.comparison.max_abs_all,
                                ok ? "<=" : ">", *limits.max_abs));
  }
  if (limits.max_off_share) {
    const bool ok = d.off_share <= *limits.max_off_share;
    v.pass = v.pass && ok;
    parts.push_back(fmt::format("off share {:.4f} % {} {:.4f} %", 100.0 * d.off_share,
                                ok ? "<=" : ">", 100.0 * *limits.max_off_share));
  }
  const std::string checked =
      parts.empty() ? std::string("no limit given") : fmt::format("{}", fmt::join(parts, ", "));
  v.summary = fmt::format("{}: {}", v.pass ? "within tolerance" : "BEYOND TOLERANCE", checked);
  return v;
}

Image heat_map(const Image& a, const Image& b, double scale) {
  Image out(a.width, a.height, Format::RGBA8);
  const size_t pixels = size_t{a.width} * a.height;
  if (a.width != b.width || a.height != b.height || a.rgba.size() != pixels * 4 ||
      b.rgba.size() != pixels * 4)
    return out;
  std::vector<double> diffs(pixels);
  double largest = 0;
  for (size_t p = 0; p < pixels; ++p) {
    diffs[p] = pixel_difference(a, b, p).first;
    if (std::isfinite(diffs[p])) largest = std::max(largest, diffs[p]);
  }
  if (scale <= 0) scale = largest;
  for (size_t p = 0; p < pixels; ++p) {
    std::array<float, 4> colour{0, 0, 0, 1};
    if (!std::isfinite(diffs[p]))
      colour = {1, 0, 1, 1};
    else if (diffs[p] > 0 && scale > 0)
      colour = heat_colour(diffs[p] / scale);
    for (int c = 0; c < 4; ++c) out.rgba[4 * p + c] = quantize(Format::RGBA8, colour[c]);
  }
  return out;
}

} // namespace tierlift::img
