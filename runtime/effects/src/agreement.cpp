#include "tierlift/effects/agreement.h"

#include <fmt/format.h>

namespace tierlift::effects {
namespace {

bool add_row(RunAgreement& out, const std::string& pass, const std::string& target,
             const img::Image& a, const img::Image& b) {
  std::string err;
  auto c = img::compare(a, b, &err);
  if (!c) {
    out.error = fmt::format("{}: {}", pass, err);
    return false;
  }
  // Judge by the format the target stores (both images carry it).
  img::Verdict v = img::judge(*c, a.format);
  out.passes.push_back({pass, target, *c, v});
  return true;
}

} // namespace

RunAgreement compare_runs(const GraphRun& a, const ImageMap& a_images, const GraphRun& b,
                          const ImageMap& b_images, const std::string& frame) {
  RunAgreement out;
  if (a.passes.size() != b.passes.size()) {
    out.error = fmt::format("the runs have {} and {} passes", a.passes.size(), b.passes.size());
    return out;
  }
  for (size_t i = 0; i < a.passes.size(); ++i) {
    const PassRecord &pa = a.passes[i], &pb = b.passes[i];
    if (pa.pass != pb.pass) {
      out.error =
          fmt::format("pass {} is '{}' in one run and '{}' in the other", i, pa.pass, pb.pass);
      return out;
    }
    if (!add_row(out, pa.pass, pa.target, pa.result, pb.result)) return out;
  }
  auto fa = a_images.find(frame), fb = b_images.find(frame);
  if (fa == a_images.end() || fb == b_images.end()) {
    out.error = fmt::format("no texture '{}' to compare as the frame", frame);
    return out;
  }
  if (!add_row(out, "frame", frame, fa->second, fb->second)) return out;
  out.all_pass = true;
  for (const PassAgreement& p : out.passes) out.all_pass = out.all_pass && p.verdict.pass;
  return out;
}

} // namespace tierlift::effects
