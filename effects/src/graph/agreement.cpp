#include "tierlift/effects/graph/agreement.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace tierlift::effects {
namespace {

// Pixels that differ where either run's device gives slack (PassDevice::rounding_midpoints:
// a proven rounding tie, one 8-bit step either way), by no more than that slack
// in every channel.
std::vector<size_t> explained_pixels(const img::Image& a, const img::Image& b,
                                     const std::vector<uint8_t>& mask_a,
                                     const std::vector<uint8_t>& mask_b) {
  const size_t pixels = size_t(a.width) * a.height;
  std::vector<size_t> out;
  if (a.format != img::Format::RGBA8 || (mask_a.size() != pixels && mask_b.size() != pixels) ||
      b.rgba.size() != a.rgba.size())
    return out;
  for (size_t p = 0; p < pixels; ++p) {
    // One step at most, whatever a mask holds: a proven rounding tie moves a store by one.
    const int slack = std::min(1, std::max(mask_a.size() == pixels ? mask_a[p] : 0,
                                           mask_b.size() == pixels ? mask_b[p] : 0));
    if (slack == 0) continue;
    bool differs = false, within_slack = true;
    for (size_t c = 0; c < 4; ++c) {
      const double d = std::fabs(double(a.rgba[4 * p + c]) - double(b.rgba[4 * p + c]));
      differs = differs || d != 0;
      within_slack = within_slack && d <= slack / 255.0 + 1e-7;
    }
    if (differs && within_slack) out.push_back(p);
  }
  return out;
}

// docs/design.md's targets per format (img::agreement_tolerance), and for RGBA16F also RGBA8's
// ≥ 99.9 % identical pixels: every way stores the same toward-zero half (the analytic model
// settles the store in the devices' fp32 arithmetic where its double value cannot), so a
// larger share of differing pixels is an error in the math, not rounding. A blur weight off
// by 0.1 % stays within 2^-10 of full scale yet changes about every half it touches.
img::Tolerance pair_tolerance(img::Format format) {
  img::Tolerance t = img::agreement_tolerance(format);
  if (format == img::Format::RGBA16F) t.min_identical_share = 0.999;
  return t;
}

// Runs that cannot be compared: one error (rule "agreement").
ir::Failure not_comparable(std::string message) {
  return ir::fail("agreement", "agreement", std::move(message));
}

// Empty on success, else why the images cannot be compared.
std::string add_row(RunAgreement& out, const std::string& pass, const std::string& target,
                    const img::Image& a, const img::Image& b, const std::vector<uint8_t>& mask_a,
                    const std::vector<uint8_t>& mask_b) {
  auto c = img::compare(a, b);
  if (!c) return fmt::format("{}: {}", pass, c.message());
  const std::vector<size_t> explained = explained_pixels(a, b, mask_a, mask_b);
  PassAgreement row{pass,
                    target,
                    *c,
                    explained.size(),
                    c->pixels ? double(explained.size()) / double(c->pixels) : 0.0,
                    c->identical_share,
                    {}};
  // The verdict sees explained pixels as identical: in the share and in the max abs.
  img::Comparison judged = *c;
  if (!explained.empty()) {
    img::Image b_explained = b;
    for (size_t p : explained)
      std::copy_n(a.rgba.begin() + 4 * p, 4, b_explained.rgba.begin() + 4 * p);
    judged = *img::compare(a, b_explained);
    judged.full_scale = c->full_scale;
  }
  row.identical_share_with_midpoints = judged.identical_share;
  // Judge by the format the target stores (both images carry it).
  row.verdict = img::judge(judged, pair_tolerance(a.format));
  out.passes.push_back(std::move(row));
  return {};
}

const std::vector<uint8_t>& mask_of(const GraphRun& run, const std::string& texture) {
  static const std::vector<uint8_t> kNone;
  auto it = run.midpoints.find(texture);
  return it == run.midpoints.end() ? kNone : it->second;
}

} // namespace

ir::Result<RunAgreement> compare_runs(const GraphRun& a, const ImageMap& a_images,
                                      const GraphRun& b, const ImageMap& b_images,
                                      const std::string& frame) {
  RunAgreement out;
  if (a.passes.size() != b.passes.size())
    return not_comparable(
        fmt::format("the runs have {} and {} passes", a.passes.size(), b.passes.size()));
  for (size_t i = 0; i < a.passes.size(); ++i) {
    const PassRecord &pa = a.passes[i], &pb = b.passes[i];
    if (pa.pass != pb.pass)
      return not_comparable(
          fmt::format("pass {} is '{}' in one run and '{}' in the other", i, pa.pass, pb.pass));
    if (std::string e =
            add_row(out, pa.pass, pa.target, pa.result, pb.result, pa.midpoints, pb.midpoints);
        !e.empty())
      return not_comparable(e);
    if (pa.more.size() != pb.more.size())
      return not_comparable(fmt::format("pass '{}' wrote {} and {} further targets", pa.pass,
                                        pa.more.size(), pb.more.size()));
    for (size_t k = 0; k < pa.more.size(); ++k)
      if (std::string e = add_row(out, pa.pass, pa.more[k].target, pa.more[k].result,
                                  pb.more[k].result, pa.more[k].midpoints, pb.more[k].midpoints);
          !e.empty())
        return not_comparable(e);
  }
  auto fa = a_images.find(frame), fb = b_images.find(frame);
  if (fa == a_images.end() || fb == b_images.end())
    return not_comparable(fmt::format("no texture '{}' to compare as the frame", frame));
  if (std::string e = add_row(out, "frame", frame, fa->second, fb->second, mask_of(a, frame),
                              mask_of(b, frame));
      !e.empty())
    return not_comparable(e);
  out.all_pass = true;
  for (const PassAgreement& p : out.passes) out.all_pass = out.all_pass && p.verdict.pass;
  return out;
}

} // namespace tierlift::effects
