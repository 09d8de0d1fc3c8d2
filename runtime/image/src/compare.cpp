// Difference metrics between two images and the pass/fail rule per target format.
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "tierlift/image/compare.h"

namespace tierlift::img {

namespace {
// Equal values, NaN equal to NaN (a NaN both ways agree on is agreement).
bool same_value(float a, float b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

} // namespace

double channel_difference(float a, float b) {
  if (same_value(a, b)) return 0.0;
  if (!std::isfinite(a) || !std::isfinite(b)) return std::numeric_limits<double>::infinity();
  return std::fabs(static_cast<double>(a) - static_cast<double>(b));
}

ir::Result<Comparison> compare(const Image& a, const Image& b) {
  auto fail = [](std::string msg) -> ir::Result<Comparison> {
    return ir::fail("compare", "size", std::move(msg));
  };
  if (a.width != b.width || a.height != b.height)
    return fail(
        fmt::format("image sizes differ: {}x{} vs {}x{}", a.width, a.height, b.width, b.height));
  const size_t n = size_t{a.width} * a.height * 4;
  if (a.rgba.size() != n || b.rgba.size() != n) return fail("image buffer size does not match");
  Comparison c;
  c.width = a.width;
  c.height = a.height;
  c.pixels = uint64_t{a.width} * a.height;
  std::array<double, 4> sq{};
  double full = 1.0;
  for (size_t p = 0; p < c.pixels; ++p) {
    bool identical = true;
    for (int ch = 0; ch < 4; ++ch) {
      float va = a.rgba[p * 4 + ch], vb = b.rgba[p * 4 + ch];
      if (std::isfinite(va)) full = std::fmax(full, std::fabs(static_cast<double>(va)));
      if (std::isfinite(vb)) full = std::fmax(full, std::fabs(static_cast<double>(vb)));
      double d = channel_difference(va, vb);
      if (d != 0.0) identical = false;
      if (std::isinf(d)) c.non_finite_mismatch = true;
      sq[ch] += d * d;
      if (d > c.max_abs[ch]) c.max_abs[ch] = d;
      if (d > c.max_abs_all) {
        c.max_abs_all = d;
        c.worst_x = static_cast<uint32_t>(p % a.width);
        c.worst_y = static_cast<uint32_t>(p / a.width);
        c.worst_channel = ch;
      }
    }
    if (identical) ++c.identical_pixels;
  }
  double total = 0;
  for (int ch = 0; ch < 4; ++ch) {
    total += sq[ch];
    c.rmse[ch] = c.pixels ? std::sqrt(sq[ch] / static_cast<double>(c.pixels)) : 0.0;
  }
  c.rmse_all = c.pixels ? std::sqrt(total / (4.0 * static_cast<double>(c.pixels))) : 0.0;
  c.identical_share =
      c.pixels ? static_cast<double>(c.identical_pixels) / static_cast<double>(c.pixels) : 1.0;
  c.full_scale = full;
  return c;
}

Tolerance agreement_tolerance(Format target) {
  switch (target) {
  case Format::RGBA32F: return {1e-5, 0.0};
  case Format::RGBA16F: return {0x1p-10, 0.0};
  case Format::RGBA8: return {1.0 / 255.0, 0.999};
  }
  return {};
}

Verdict judge(const Comparison& c, const Tolerance& t) {
  // RGBA8 differences are multiples of 1/255 computed from floats: allow float noise. Two
  // stored values k/255 near 1.0 are each rounded to float, so their difference can exceed
  // 1/255 by ~1.5e-5 relative (measured on the glow); 1e-4 still keeps 2 LSB far away.
  const double limit = t.max_abs_relative * c.full_scale * (1.0 + 1e-4);
  bool ok_max = c.max_abs_all <= limit;
  bool ok_share = t.min_identical_share <= 0 || c.identical_share >= t.min_identical_share;
  Verdict v;
  v.pass = ok_max && ok_share;
  v.summary = fmt::format("{}: {} (limit max abs {:.3g}", v.pass ? "agree" : "DISAGREE",
                          describe(c), limit);
  if (t.min_identical_share > 0)
    v.summary += fmt::format(", identical >= {:.2f} %", 100.0 * t.min_identical_share);
  v.summary += ")";
  return v;
}

Verdict judge(const Comparison& c, Format target) {
  return judge(c, agreement_tolerance(target));
}

std::string describe(const Comparison& c) {
  static const char* names = "RGBA";
  return fmt::format("max abs {:.3g} ({} at {},{}), rmse {:.3g}, identical {:.3f} %", c.max_abs_all,
                     names[c.worst_channel], c.worst_x, c.worst_y, c.rmse_all,
                     100.0 * c.identical_share);
}

} // namespace tierlift::img
