#include "glow_report.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "tierlift/effects/glow/glow.h"
#include "tierlift/image/io.h"
#include "tierlift/io/output_file.h"

namespace tierlift::cli {

void print_agreement_table(const std::vector<effects::PairAgreement>& pairs) {
  if (pairs.empty()) return;
  constexpr int kCell = 28; // "  max abs     rmse   ident."
  std::string head = fmt::format("{:<12} {:<13}", "", "");
  std::string cols = fmt::format("{:<12} {:<13}", "pass", "target");
  for (const effects::PairAgreement& p : pairs) {
    head += fmt::format(" {:^{}}", fmt::format("{} · {}", p.a, p.b), kCell);
    cols += fmt::format(" {:>9} {:>9} {:>8}", "max abs", "rmse", "ident.");
  }
  fmt::print("{}\n{}\n", head, cols);
  const size_t rows = pairs.front().agreement.passes.size();
  for (size_t r = 0; r < rows; ++r) {
    const effects::PassAgreement& first = pairs.front().agreement.passes[r];
    std::string line = fmt::format("{:<12} {:<13}", first.pass, first.target);
    for (const effects::PairAgreement& p : pairs) {
      const effects::PassAgreement& row = p.agreement.passes[r];
      const img::Comparison& c = row.comparison;
      line += fmt::format(" {:>9.2g} {:>9.2g} {:>7.3f}%{}", c.max_abs_all, c.rmse_all,
                          100.0 * row.identical_share_with_midpoints, row.verdict.pass ? "" : "!");
      if (row.verdict.pass) line += " ";
    }
    fmt::print("{}\n", line);
  }
  uint64_t midpoints = 0;
  double most = 0;
  for (const effects::PairAgreement& p : pairs)
    for (const effects::PassAgreement& row : p.agreement.passes) {
      midpoints += row.midpoint_pixels;
      most = std::max(most, row.midpoint_share);
    }
  if (midpoints > 0) // RGBA8 only; --json reports midpoint_share for every row
    fmt::print("slack used: {} pixels (summed over rows and pairs; at most {:.4f} % of a row) "
               "one 8-bit step apart\nwhere the analytic model proved a rounding tie, counted "
               "in ident.\n",
               midpoints, 100.0 * most);
}

nlohmann::json agreement_json(const std::vector<effects::PairAgreement>& pairs) {
  nlohmann::json out = nlohmann::json::array();
  for (const effects::PairAgreement& p : pairs) {
    nlohmann::json rows = nlohmann::json::array();
    for (const effects::PassAgreement& row : p.agreement.passes)
      rows.push_back({{"pass", row.pass},
                      {"target", row.target},
                      {"max_abs", row.comparison.max_abs_all},
                      {"rmse", row.comparison.rmse_all},
                      {"identical_share", row.comparison.identical_share},
                      {"midpoint_pixels", row.midpoint_pixels},
                      {"midpoint_share", row.midpoint_share},
                      {"identical_share_with_midpoints", row.identical_share_with_midpoints},
                      {"within_targets", row.verdict.pass},
                      {"summary", row.verdict.summary}});
    out.push_back(
        {{"pair", {p.a, p.b}}, {"rows", rows}, {"all_within_targets", p.agreement.all_pass}});
  }
  return out;
}

std::string write_glow_images(io::OutputFolder& out, const std::vector<effects::WayRun>& ways,
                              bool float_targets) {
  struct File {
    std::string name;
    const img::Image* image;
    bool pfm;
  };
  std::vector<File> files;
  for (const effects::WayRun& way : ways)
    for (std::string_view tex :
         {effects::kSceneTexture, effects::kGlowTexture, effects::kFinalTexture}) {
      const auto it = way.glow.images.find(tex);
      if (it == way.glow.images.end()) continue;
      const std::string base = fmt::format("{}-{}", tex, way.name);
      files.push_back({base + ".png", &it->second, false});
      if (float_targets) files.push_back({base + ".pfm", &it->second, true});
    }
  // Every name is checked (never one of the inputs) before the first is written.
  std::vector<std::string> paths;
  for (const File& f : files) {
    ir::Result<std::string> path = out.path(f.name);
    if (!path) return path.message();
    paths.push_back(*path);
  }
  for (size_t i = 0; i < files.size(); ++i) {
    const File& f = files[i];
    auto write = [&]() -> ir::Status {
      if (f.pfm) return img::write_pfm(paths[i], *f.image);
      img::Image opaque = *f.image;
      for (size_t k = 3; k < opaque.rgba.size(); k += 4) opaque.rgba[k] = 1.0f;
      return img::write_png(paths[i], opaque);
    };
    if (ir::Status s = write(); !s) return s.message();
  }
  return {};
}

void print_frames_table(const std::vector<effects::FrameReport>& frames) {
  if (frames.empty()) return;
  fmt::print("frames: setup once, then {} steady-state frame(s) per device\n",
             frames.front().times.frame_ms.size());
  fmt::print("{:<10} {:>10} {:>10} {:>10} {:>10}\n", "device", "setup ms", "median ms", "min ms",
             "max ms");
  for (const effects::FrameReport& r : frames)
    fmt::print("{:<10} {:>10.1f} {:>10.2f} {:>10.2f} {:>10.2f}\n", r.device, r.times.setup_ms,
               r.times.median_ms(), r.times.min_ms(), r.times.max_ms());
}

nlohmann::json frames_json(const std::vector<effects::FrameReport>& frames) {
  nlohmann::json j = nlohmann::json::object();
  for (const effects::FrameReport& r : frames)
    j[r.device] = {{"setup_ms", r.times.setup_ms},
                   {"median_ms", r.times.median_ms()},
                   {"min_ms", r.times.min_ms()},
                   {"max_ms", r.times.max_ms()},
                   {"n", r.times.frame_ms.size()}};
  return j;
}

void print_pruning(const effects::PrunedGraph& pruned, bool no_prune, bool varies) {
  fmt::print("pruning {}: {} of {} passes left out, {} limited to the sources' box{}\n",
             no_prune ? "off (--no-prune)" : "on", varies ? 0 : pruned.left_out.size(),
             pruned.passes_before, varies ? 0 : pruned.limited.size(),
             varies ? " (the scene changes from frame to frame: pruning bounds values from "
                      "one image, so the whole plan runs)"
             : !pruned.changed() ? " (the scene needs every pass, everywhere)"
                                 : "");
  const std::vector<effects::LeftOut> none;
  for (const effects::LeftOut& l : varies ? none : pruned.left_out)
    fmt::print("  {} {}: {}\n", no_prune ? "would leave out" : "left out", l.what, l.why);
  for (const effects::LeftOut& l : varies ? none : pruned.limited)
    fmt::print("  {} {}: {}\n", no_prune ? "would limit" : "limited", l.what, l.why);
  for (const effects::LeftOut& k : varies ? none : pruned.kept)
    fmt::print("  kept {}: {}\n", k.what, k.why);
  fmt::print("  kept: the SPIR-V pair pruning of every pass (unused constants, inputs and "
             "outputs; tierlift spirv --pair --explain)\n");
}

nlohmann::json pruning_json(const effects::PrunedGraph& pruned, bool enabled) {
  auto list = [](const std::vector<effects::LeftOut>& items) {
    nlohmann::json out = nlohmann::json::array();
    for (const effects::LeftOut& l : items) out.push_back({{"what", l.what}, {"why", l.why}});
    return out;
  };
  return {{"enabled", enabled},
          {"left_out", list(pruned.left_out)},
          {"limited", list(pruned.limited)},
          {"kept", list(pruned.kept)}};
}

} // namespace tierlift::cli
