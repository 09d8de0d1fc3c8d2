// run_single_pass: `tierlift run`'s graph of one pass on the CPU device, the Vulkan device or
// both, compared (single_pass.h).
#include <memory>
#include <new>
#include <optional>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "tierlift/effects/graph/device.h"
#include "tierlift/effects/graph/memory_plan.h"
#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/effects/graph/single_pass.h"

namespace tierlift::effects {
namespace {

ir::Diagnostic error(std::string rule, std::string message, std::string subject = "") {
  return {ir::Severity::Error, {}, std::move(message), std::move(rule), std::move(subject)};
}

// The target's size and format, from the graph's one target.
const TextureDesc& target_of(const EffectGraph& graph) {
  return *graph.find_texture(kSinglePassTarget);
}

// One device's draw; on failure `told` gets its diagnostics (the error's subject: the device).
std::optional<SinglePassDraw> draw_on(PassDevice& device, const EffectGraph& graph,
                                      std::vector<ir::Diagnostic>& told) {
  const TextureDesc& t = target_of(graph);
  ImageMap images;
  std::optional<ir::Result<GraphRun>> run;
  try { // a 16384² float target is 4 GiB: running out of memory is an error, not a crash
    // Whether the host can hold the image that comes back, asked first (allocated, never
    // touched; an explicit operator new, which no compiler may leave out): a host out of
    // memory is this error on every device, not a device's refusal.
    ::operator delete(::operator new (size_t{t.width} * t.height * 4 * sizeof(float)));
    run.emplace(run_graph(graph, device, images));
  } catch (const std::bad_alloc&) {
    told.push_back(error("memory", fmt::format("not enough memory for a {}x{} target and its "
                                               "textures",
                                               t.width, t.height)));
    return std::nullopt;
  }
  if (!*run) {
    for (ir::Diagnostic d : run->diagnostics()) {
      if (d.severity == ir::Severity::Error) d.subject = device.name();
      told.push_back(std::move(d));
    }
    return std::nullopt;
  }
  const PassRecord& pass = (*run)->passes.front();
  for (const ir::Diagnostic& d : pass.warnings) told.push_back(d);
  SinglePassDraw out{
      device.name(), std::move(images.at(std::string(kSinglePassTarget))), pass.report, {}, {}};
  out.report.setup_ms = (*run)->setup_ms; // textures, uploads, pipelines
  out.report.draw_ms = pass.ms;           // the pass, to the end of its work on the device
  for (uint32_t i = 1;; ++i) {            // oC1..: the graph's further targets, in order
    auto more = images.find(single_pass_target(i));
    if (more == images.end()) break;
    out.more_images.push_back(std::move(more->second));
  }
  if (auto z = images.find(kSinglePassDepth); z != images.end()) out.depth = std::move(z->second);
  return out;
}

ir::Failure failed(std::vector<ir::Diagnostic> told) {
  return ir::Failure{std::move(told)};
}

} // namespace

ir::Result<SinglePassRun> run_single_pass(const EffectGraph& graph, const BackendChoice& backends,
                                          const vulkan::DeviceOptions& vulkan, unsigned threads) {
  const TextureDesc& t = target_of(graph);
  std::vector<ir::Diagnostic> told;
  // Memory known before anything is allocated (plan_memory), as a scene plans it.
  if (std::string why = memory_refusal(
          plan_memory(graph, backends.ways, false, kProgramBytes), available_memory(),
          fmt::format("the {}x{} {} target on {}", t.width, t.height, img::format_name(t.format),
                      fmt::join(backends.ways, " + ")));
      !why.empty())
    return failed(
        {error("memory", why + "; a smaller --size or --format, or one backend, needs less")});
  // "all" leaves Vulkan out, with a note, where the machine has none (select_ways).
  ir::Result<SelectedWays> selected = select_ways(backends, vulkan);
  if (!selected) return failed({error("device", selected.message())});
  SinglePassRun out;
  out.selected = std::move(selected).value();
  if (!out.selected.note.empty())
    told.push_back({ir::Severity::Warning, {}, out.selected.note, "backend", ""});
  for (const std::string& way : out.selected.ways) {
    std::unique_ptr<PassDevice> device;
    if (way == "cpu") device = std::make_unique<CpuPassDevice>(threads);
    if (way == "vulkan" && out.selected.vulkan) {
      out.vulkan_device = out.selected.vulkan->name();
      device = make_vulkan_pass_device(*out.selected.vulkan);
    }
    if (!device) continue; // a way this command does not offer (parse_backends refused it)
    std::optional<SinglePassDraw> drawn = draw_on(*device, graph, told);
    if (!drawn) return failed(std::move(told));
    out.draws.push_back(std::move(*drawn));
  }
  if (out.draws.size() == 2) {
    ir::Result<img::Comparison> compared = img::compare(out.draws[0].image, out.draws[1].image);
    if (!compared) {
      told.push_back(error("agreement", compared.message()));
      return failed(std::move(told));
    }
    out.agreement = *compared;
    out.verdict = img::judge(*out.agreement, t.format);
    const auto& [a, b] = std::tie(out.draws[0], out.draws[1]);
    for (size_t i = 0; i < a.more_images.size() && i < b.more_images.size(); ++i) {
      ir::Result<img::Comparison> more = img::compare(a.more_images[i], b.more_images[i]);
      if (!more) {
        told.push_back(error("agreement", more.message()));
        return failed(std::move(told));
      }
      out.more_agreement.push_back(*more);
      out.more_verdicts.push_back(img::judge(*more, t.format));
    }
    if (a.depth && b.depth) {
      ir::Result<img::Comparison> z = img::compare(*a.depth, *b.depth);
      if (!z) {
        told.push_back(error("agreement", z.message()));
        return failed(std::move(told));
      }
      out.depth_agreement = *z;
      const bool same = z->identical_pixels == z->pixels;
      out.depth_verdict =
          img::Verdict{same, fmt::format("{}: {}", img::describe(*z),
                                         same ? "bit for bit, as the depth rule requires"
                                              : "NOT bit for bit (the depth rule requires it)")};
    }
  }
  ir::Result<SinglePassRun> result(std::move(out));
  for (ir::Diagnostic& d : told) result.add(std::move(d));
  return result;
}

} // namespace tierlift::effects
