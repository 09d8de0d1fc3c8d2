// tierlift run: one pass of a vertex and/or pixel listing over the full-screen quad, a graph of
// one pass: the flags become one pass::Pass (pass::prepare_pass: listings and textures read
// once), that pass a graph of one pass (effects::single_pass_graph), which run_graph runs on
// the CPU device, the Vulkan device or both, through the one device interface
// (effects::PassDevice) every effect uses. Only flags and printing live here.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <memory>
#include <new>
#include <optional>
#include <string_view>

#include "commands.h"
#include "front_end.h"
#include "report.h"
#include "run_depth.h"
#include "run_files.h"
#include "run_flags.h"
#include "run_output.h"
#include "run_request.h"
#include "run_trace.h"
#include "tierlift/effects/graph/backends.h"
#include "tierlift/effects/graph/device.h"
#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/effects/graph/single_pass.h"
#include "tierlift/image/compare.h"
#include "tierlift/ir/ps1x_range.h"

namespace tierlift::cli {
namespace {

void print_other(const ir::DiagnosticSink& sink, Report& report) {
  for (const ir::Diagnostic& d : sink.all()) {
    if (d.severity == ir::Severity::Error)
      report.error(d.rule, d.message);
    else
      report.warning(d.rule, d.message);
  }
}

// A failed run as `tierlift run` has always worded a draw the device refused: the device's
// own words (run_graph hands them on as notes after its summary), under rule "draw" on the
// CPU and as "vulkan: …" on Vulkan; the run's summary when there are none. The graph's one
// pass is the whole draw, so a device's "pass 'run': " adds nothing and is left out. The
// failing device is the subject of run_single_pass's error.
void report_failure(const std::vector<ir::Diagnostic>& diagnostics, Report& report) {
  const std::string pass_prefix = fmt::format("pass '{}': ", effects::kSinglePass);
  std::string device;
  for (const ir::Diagnostic& d : diagnostics)
    if (d.severity == ir::Severity::Error) device = d.subject;
  bool cause = false;
  for (const ir::Diagnostic& d : diagnostics) {
    if (d.severity != ir::Severity::Note) continue; // only the device's cause is a note
    std::string_view why = d.message;
    if (why.starts_with(pass_prefix)) why.remove_prefix(pass_prefix.size());
    if (device == "vulkan")
      report.error("vulkan", "vulkan: " + std::string(why));
    else
      report.error("draw", std::string(why));
    cause = true;
  }
  if (cause) return;
  for (const ir::Diagnostic& d : diagnostics)
    if (d.severity == ir::Severity::Error) report.error(d.rule, d.message);
}

// run_single_pass's warnings and failure, in the order they arose; the exit code of the
// failure (a device that cannot be had: usage), kExitOk without one.
int report_single_pass(const ir::Result<effects::SinglePassRun>& ran, Report& report) {
  for (const ir::Diagnostic& d : ran.diagnostics())
    if (d.severity == ir::Severity::Warning) report.warning(d.rule, d.message);
  if (ran) return kExitOk;
  std::vector<ir::Diagnostic> failure;
  for (const ir::Diagnostic& d : ran.diagnostics())
    if (d.severity != ir::Severity::Warning) failure.push_back(d);
  for (const ir::Diagnostic& d : failure)
    if (d.severity == ir::Severity::Error &&
        (d.rule == "memory" || d.rule == "device" || d.rule == "agreement")) {
      report.error(d.rule, d.message);
      return d.rule == "device" ? kExitUsage : kExitInvalid;
    }
  report_failure(failure, report);
  return kExitInvalid;
}

// One device's draw as the run's output shows it: the image, its probes, what it took.
DeviceRun shown_run(const effects::SinglePassDraw& draw, const pass::RunRequest& req) {
  DeviceRun out;
  out.ok = true;
  out.image = draw.image;
  out.more_images = draw.more_images;
  out.probes = pass::read_probes(out.image, req.probes);
  out.report = draw.report;
  return out;
}

// --output1..3 as given: [oC1's file or null, …] up to the last render target asked for.
nlohmann::json more_outputs_json(const RunFlags& f) {
  nlohmann::json out = nlohmann::json::array();
  for (const std::string& o : f.more_outputs)
    if (!o.empty()) out.push_back(o);
  return out;
}

nlohmann::json result_json(const RunFlags& f, const pass::RunRequest& r, const DeviceRun& run,
                           double write_ms) {
  nlohmann::json probes = nlohmann::json::array();
  for (const auto& p : run.probes)
    probes.push_back(
        {{"x", p.x}, {"y", p.y}, {"rgba", {p.value[0], p.value[1], p.value[2], p.value[3]}}});
  return {{"size", {{"width", r.width}, {"height", r.height}}},
          {"format", img::format_name(r.format)},
          {"ps1x_max",
           {{"preset", ir::ps1x_max_label(r.conventions.ps1x_max_value)},
            {"value", r.conventions.ps1x_max_value}}},
          {"probes", probes},
          {"output", f.output.empty() ? nlohmann::json() : nlohmann::json(f.output)},
          {"more_outputs", more_outputs_json(f)},
          {"pixels_shaded", run.report.pixels_shaded},
          {"pixels_killed", run.report.pixels_killed},
          {"timing_ms",
           {{"setup", run.report.setup_ms}, {"draw", run.report.draw_ms}, {"write", write_ms}}}};
}

// What the flags ask for before any file is read: the request (every flag but --const),
// the ways, the trace. Every flag is checked here; --const may name a constant of a token
// stream's CTAB, so it is read once the listings are loaded (resolve_constants).
struct RunPlan {
  pass::RunRequest req;
  effects::BackendChoice backends;
  bool cpu = false, vulkan = false; // the ways asked for
  std::optional<PixelTraceRequest> trace;
};

// The plan, or nullopt after reporting a usage error (exit 2).
std::optional<RunPlan> plan_from_flags(const RunFlags& f, Report& report) {
  RunPlan plan;
  ir::Result<pass::RunRequest> req = build_request(f);
  if (!req) {
    report.error("usage", req.message());
    return std::nullopt;
  }
  plan.req = std::move(req).value();
  ir::Result<effects::BackendChoice> backends =
      effects::parse_backends(f.backend, {"cpu", "vulkan"});
  if (!backends) {
    report.error("usage", backends.message());
    return std::nullopt;
  }
  plan.backends = std::move(backends).value();
  auto wants = [&](const char* way) {
    return std::find(plan.backends.ways.begin(), plan.backends.ways.end(), way) !=
           plan.backends.ways.end();
  };
  plan.cpu = wants("cpu");
  plan.vulkan = wants("vulkan");
  ir::Result<std::optional<PixelTraceRequest>> traced =
      trace_request(f.trace, !f.ps.empty(), plan.req, plan.cpu, plan.vulkan, f.gpu);
  if (!traced) {
    report.error("usage", traced.message());
    return std::nullopt;
  }
  plan.trace = *traced;
  return plan;
}

struct Listings {
  std::optional<LoadedListing> vs, ps; // each keeps its own SourceManager
};

// The listings read, checked and their diagnostics reported; kExitOk, or the exit code after
// reporting why not.
int load_listings(const RunFlags& f, const RunPlan& plan, Listings& out, Report& report) {
  for (auto [path, slot] : {std::pair{&f.vs, &out.vs}, std::pair{&f.ps, &out.ps}}) {
    if (path->empty()) continue;
    ir::Result<LoadedListing> loaded = load_listing(*path, f.fe);
    if (!loaded) {
      report.error("io", loaded.message(), *path);
      return kExitUsage;
    }
    *slot = std::move(loaded).value();
  }
  bool listings_ok = true;
  for (auto* l : {&out.vs, &out.ps}) {
    if (!*l) continue;
    if ((*l)->program && !check_executable(**l, plan.cpu ? "the interpreter" : "SPIR-V"))
      listings_ok = false;
    report.diagnostics((*l)->diags, (*l)->sources);
    listings_ok = listings_ok && (*l)->program && !(*l)->diags.has_errors();
  }
  if (!listings_ok) return kExitInvalid;
  for (const std::string& o : output_files(f, plan.cpu && plan.vulkan))
    for (auto* l : {&out.vs, &out.ps})
      if (ir::Status refused = *l ? refuse_included(o, **l) : ir::ok_status(); !refused) {
        report.error("io", refused.message(), o);
        return kExitUsage;
      }
  return kExitOk;
}

// --const, names in a token stream's CTAB resolved to the registers they cover, and the
// listings' programs into the request. False after reporting a usage error.
bool complete_request(const RunFlags& f, const Listings& l, pass::RunRequest& req, Report& report) {
  auto table = [](const std::optional<LoadedListing>& listing) {
    return listing && listing->constants ? &*listing->constants : nullptr;
  };
  ir::Result<std::vector<pass::ConstSetting>> consts =
      parse_const_assignments(f.consts, table(l.vs), table(l.ps));
  if (!consts) {
    report.error("usage", consts.message());
    return false;
  }
  req.constants = std::move(*consts);
  if (l.vs) req.vs = std::make_shared<const ir::Program>(*l.vs->program);
  if (l.ps) req.ps = std::make_shared<const ir::Program>(*l.ps->program);
  return true;
}

// The one pass both devices draw (listings, constants and textures read once), its
// diagnostics reported; nullopt with `exit_code` set when it cannot be made.
std::optional<pass::Pass> prepare(const pass::RunRequest& req, const Listings& l, Report& report,
                                  double& prepare_ms, int& exit_code) {
  const auto t0 = std::chrono::steady_clock::now();
  pass::RunDiagnostics diags;
  std::optional<pass::Pass> prepared;
  ir::Result<pass::Pass> made = pass::prepare_pass(req);
  pass::add_by_listing(diags, made.diagnostics());
  if (made) prepared = std::move(made).value();
  prepare_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (l.vs) report.diagnostics(diags.vs, l.vs->sources);
  if (l.ps) report.diagnostics(diags.ps, l.ps->sources);
  print_other(diags.other, report);
  exit_code = kExitInvalid;
  for (const auto& e : diags.other.all())
    if (e.severity == ir::Severity::Error && pass::is_usage_rule(e.rule)) exit_code = kExitUsage;
  return prepared;
}

// The image(s) to -o and --output1..3 (the Vulkan one beside the CPU one with two ways),
// each file written whole or not at all; the time it took, or nullopt after reporting an I/O
// error.
std::optional<double> write_outputs(const RunFlags& f, const DeviceRun& shown, const DeviceRun* vk,
                                    Report& report) {
  auto t0 = std::chrono::steady_clock::now();
  std::vector<std::pair<std::string, const img::Image*>> files;
  auto add = [&](const std::string& path, const DeviceRun& run, size_t target) {
    if (path.empty()) return;
    const img::Image* image =
        target == 0 ? &run.image
                    : (target <= run.more_images.size() ? &run.more_images[target - 1] : nullptr);
    if (image) files.emplace_back(path, image);
  };
  for (size_t t = 0; t <= f.more_outputs.size(); ++t) {
    const std::string& path = t == 0 ? f.output : f.more_outputs[t - 1];
    add(path, shown, t);
    if (vk && !path.empty()) add(vulkan_output(path), *vk, t);
  }
  for (const auto& [path, image] : files) {
    std::string warning;
    std::string err = write_run_output(path, *image, &warning, f.keep_alpha);
    if (!warning.empty()) report.warning("clamped", warning, path);
    if (!err.empty()) {
      report.error("io", err, path);
      return std::nullopt;
    }
  }
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

nlohmann::json run_json(const RunFlags& f, const pass::RunRequest& req,
                        const effects::SinglePassRun& r, const DeviceRun& shown,
                        const DeviceRun& vk, double write_ms) {
  nlohmann::json j = result_json(f, req, shown, write_ms);
  j["backend"] = f.backend;
  j["backends"] = {{"ran", r.selected.ways}, {"note", r.selected.note}};
  j["inputs"] = input_sources_json(req);
  if (!r.vulkan_device.empty()) j["vulkan_device"] = r.vulkan_device;
  if (r.agreement) {
    j["agreement"] = {{"max_abs", r.agreement->max_abs},
                      {"rmse", r.agreement->rmse},
                      {"identical_share", r.agreement->identical_share},
                      {"within_targets", r.verdict->pass},
                      {"summary", r.verdict->summary}};
    nlohmann::json more = nlohmann::json::array();
    for (size_t i = 0; i < r.more_agreement.size(); ++i)
      more.push_back({{"target", i + 1},
                      {"max_abs", r.more_agreement[i].max_abs},
                      {"identical_share", r.more_agreement[i].identical_share},
                      {"within_targets", r.more_verdicts[i].pass},
                      {"summary", r.more_verdicts[i].summary}});
    if (!more.empty()) j["agreement"]["more_targets"] = more;
    j["timing_ms"]["vulkan_setup"] = vk.report.setup_ms;
    j["timing_ms"]["vulkan_draw"] = vk.report.draw_ms;
  }
  return j;
}

int run(const RunFlags& f) {
  Report report("run", f.fe.json);
  // Without listings the quad shows its pixel inputs (--input); with none of the three
  // there is nothing to draw, and a bare `tierlift run` is a usage error.
  if (f.vs.empty() && f.ps.empty() && f.inputs.empty()) {
    report.error("usage", "nothing to draw: give --vs, --ps or --input (tierlift run --help)");
    return report.finish(kExitUsage);
  }
  std::optional<RunPlan> plan = plan_from_flags(f, report);
  if (!plan || !outputs_ok(f, plan->req, plan->cpu && plan->vulkan, report))
    return report.finish(kExitUsage);
  pass::RunRequest& req = plan->req;
  Listings listings;
  if (int code = load_listings(f, *plan, listings, report); code != kExitOk)
    return report.finish(code);
  if (!complete_request(f, listings, req, report)) return report.finish(kExitUsage);
  ir::Result<effects::SinglePassDepth> depth = depth_start(f, req.width, req.height);
  if (!depth) {
    report.error(ir::failed_with(depth, "io") ? "io" : "usage", depth.message());
    return report.finish(kExitUsage);
  }
  report_input_sources(req, report);
  double prepare_ms = 0;
  int exit_code = kExitOk;
  std::optional<pass::Pass> prepared = prepare(req, listings, report, prepare_ms, exit_code);
  if (!prepared) return report.finish(exit_code);
  // The same graph of one pass on each device asked for, through the one device interface.
  // The draw moves into the graph (its images shared, not copied); only a trace keeps it.
  std::optional<pass::Pass> traced;
  if (plan->trace) traced = *prepared;
  ir::Result<effects::EffectGraph> graph =
      effects::single_pass_graph(std::move(*prepared), req.width, req.height, req.format, *depth);
  prepared.reset();
  if (!graph) {
    report.error("graph", graph.message());
    return report.finish(kExitInvalid);
  }
  vulkan::DeviceOptions vk_options;
  vk_options.gpu_filter = f.gpu;
  ir::Result<effects::SinglePassRun> ran =
      effects::run_single_pass(*graph, plan->backends, vk_options, req.threads);
  if (int code = report_single_pass(ran, report); code != kExitOk) return report.finish(code);
  const effects::SinglePassRun& r = *ran;
  if (plan->trace) plan->trace->vulkan = r.selected.vulkan != nullptr; // "all" may leave it out
  // What the run reports as its image and probes: the CPU device's, else the Vulkan one's.
  DeviceRun shown = shown_run(r.draws.front(), req), vk;
  if (r.draws.front().device == "cpu") shown.report.setup_ms += prepare_ms;
  if (r.draws.back().device == "vulkan") vk = shown_run(r.draws.back(), req);
  const bool both = r.draws.size() == 2;
  const std::optional<double> write_ms = write_outputs(f, shown, both ? &vk : nullptr, report);
  if (!write_ms) return report.finish(kExitUsage);
  if (std::string err = write_depth_outputs(f, r); !err.empty()) {
    report.error("io", err, f.depth_out);
    return report.finish(kExitUsage);
  }
  if (report.json()) {
    report.result() = run_json(f, req, r, shown, vk, *write_ms);
    report.result()["depth"] = depth_json(f, req.depth_stencil, r);
  } else {
    print_text_result(shown, vk, r.vulkan_device, r.agreement, r.verdict);
    print_depth_agreement(r);
  }
  for (size_t i = 0; i < r.more_agreement.size() && !report.json(); ++i)
    fmt::print("oC{}: cpu vs vulkan: max abs per channel {:.3g} {:.3g} {:.3g} {:.3g}, identical "
               "pixels {:.2f} %: {}\n",
               i + 1, r.more_agreement[i].max_abs[0], r.more_agreement[i].max_abs[1],
               r.more_agreement[i].max_abs[2], r.more_agreement[i].max_abs[3],
               r.more_agreement[i].identical_share * 100.0,
               r.more_verdicts[i].pass ? "within targets" : "BEYOND TARGETS");
  if (plan->trace)
    if (int code = print_pixel_trace(*traced, *plan->trace, report)) return report.finish(code);
  if (r.verdict && !r.verdict->pass) {
    report.error("agreement", r.verdict->summary);
    return report.finish(kExitInvalid);
  }
  for (size_t i = 0; i < r.more_verdicts.size(); ++i)
    if (!r.more_verdicts[i].pass) {
      report.error("agreement", fmt::format("oC{}: {}", i + 1, r.more_verdicts[i].summary));
      return report.finish(kExitInvalid);
    }
  if (r.depth_verdict && !r.depth_verdict->pass) {
    report.error("agreement", "depth: " + r.depth_verdict->summary);
    return report.finish(kExitInvalid);
  }
  return report.finish(kExitOk);
}

} // namespace

void register_run_command(CLI::App& app) {
  auto f = std::make_shared<RunFlags>();
  CLI::App* sub =
      app.add_subcommand("run", "Draw one pass (vertex and/or pixel listing) over the full-screen "
                                "quad on the CPU interpreter, on Vulkan, or both");
  sub->add_option("--vs", f->vs, "Vertex listing (vs_1_1, vs_2_0)");
  sub->add_option("--ps", f->ps,
                  "Pixel listing (ps_1_1 .. ps_2_0); none: oD0 passes through. Without --vs "
                  "its t# are the quad's uv unless --input sets them");
  sub->add_option("--size", f->size, "Render target WxH (up to 16384x16384)")
      ->capture_default_str();
  // rgba32f by default, as glow: lossless, so comparisons see the shader's own values.
  sub->add_option("--format", f->format, "Render target format: rgba8 | rgba16f | rgba32f")
      ->capture_default_str();
  sub->add_option("--const", f->consts,
                  "[vs:|ps:]cN=x,y,z,w, iN=a,b,c,d, bN=true|false, or NAME=… for a constant "
                  "named in a token stream's CTAB (no prefix: both stages)");
  sub->add_option("--input", f->inputs, "Pixel-stage input v#|t#=x,y,z,w (without --vs)");
  sub->add_option("--attr", f->attrs, "Vertex input vN=x,y,z,w or vN=quad-uv (with --vs)");
  sub->add_option("--texture", f->textures,
                  "[vs:|ps:]sN=FILE.png|FILE.pfm|builtin:NAME[:WxH]|cube:F0,..,F5|volume:S0,..|"
                  "mips:L0,L1,.. (a 2D texture's levels); no prefix: the pixel stage's s0..s15, "
                  "vs: the vertex stage's s0..s3 (vs_3_0 texldl)");
  sub->add_option("--mips", f->mips,
                  "auto | N: give every one-image 2D texture a mip chain of N levels (auto: the "
                  "full chain), each a 2x2 box of the previous")
      ->capture_default_str();
  sub->add_option("--mip-filter", f->mip_filter, "none | point | linear (all samplers)")
      ->capture_default_str();
  sub->add_option("--lod-bias", f->lod_bias, "MIPMAPLODBIAS: added to every lod (all samplers)")
      ->capture_default_str();
  sub->add_option("--max-mip-level", f->max_mip_level,
                  "MAXMIPLEVEL: the most detailed level a read may take (all samplers)")
      ->capture_default_str();
  sub->add_option("--bump-matrix", f->bumps,
                  "STAGE=m00,m01,m10,m11: texbem/texbeml's bump matrix of texture stage STAGE "
                  "(default 0: no offset)");
  sub->add_option("--filter", f->filter, "point | linear (all samplers)")->capture_default_str();
  sub->add_option("--address", f->address, "clamp | wrap | mirror | border (all samplers)")
      ->capture_default_str();
  sub->add_flag("--srgb-texture", f->srgb_texture,
                "SRGBTEXTURE on every sampler: RGBA8 textures' colour decoded from sRGB to "
                "linear before filtering");
  sub->add_flag("--srgb-write", f->srgb_write,
                "SRGBWRITEENABLE: colour encoded from linear to sRGB before blending and the "
                "store, on an rgba8 target");
  sub->add_option("--pixel-center", f->pixel_center, "d3d9 | modern")->capture_default_str();
  sub->add_option("--front-face", f->front_face,
                  "cw | ccw: the on-screen winding ps_3_0's vFace calls front (+1); the "
                  "full-screen quad is clockwise")
      ->capture_default_str();
  sub->add_option("--subtexel-bits", f->subtexel_bits, "Bilinear fraction bits (0 = exact)")
      ->capture_default_str();
  sub->add_option("--ps1x-max", f->ps1x_max,
                  "ps_1_x register range (MaxPixelShaderValue): " + ir::ps1x_choices())
      ->capture_default_str();
  sub->add_option("--probe", f->probes, "Print the stored value of pixel X,Y");
  sub->add_flag("--keep-alpha", f->keep_alpha,
                "PNG: keep the shader's alpha (default: opaque, so viewers show the colour)");
  sub->add_option("-o,--output", f->output,
                  "Write the image (.png, or .pfm for float RGB; '-': PNG on standard output)");
  for (size_t i = 0; i < f->more_outputs.size(); ++i)
    sub->add_option(fmt::format("--output{}", i + 1), f->more_outputs[i],
                    fmt::format("Draw oC{} into a further render target (D3D9 MRT) of the "
                                "same size and format and write it (.png or .pfm); the lower "
                                "--outputN are needed too",
                                i + 1));
  sub->add_option("--depth-func", f->depth_func,
                  "Draw with a depth buffer, D3DRS_ZFUNC: never | less | equal | lessequal "
                  "(default) | greater | notequal | greaterequal | always");
  sub->add_option("--depth-write", f->depth_write,
                  "Draw with a depth buffer, D3DRS_ZWRITEENABLE: on (default) | off");
  sub->add_option("--depth-clear", f->depth_clear,
                  "Draw with a depth buffer cleared to V in [0, 1] (default 1)");
  sub->add_option("--depth-in", f->depth_in,
                  "Draw with a depth buffer starting as FILE.pfm's red channel (target-sized, "
                  "values in [0, 1])");
  sub->add_option("--depth-out", f->depth_out,
                  "Draw with a depth buffer and write it after the draw (.pfm, one float per "
                  "pixel; with --backend both the Vulkan one beside it)");
  add_front_end_options(sub, f->fe, true);
  sub->add_option("--threads", f->threads, "Worker threads (0 = every core)")
      ->capture_default_str();
  sub->add_option("--backend", f->backend,
                  "cpu | vulkan | both, or a list such as vulkan,cpu (both: compare the two "
                  "devices at the agreement targets; all: both where the machine has Vulkan, "
                  "else cpu with a note)")
      ->capture_default_str();
  sub->add_option("--gpu", f->gpu, "Vulkan device name filter (default: lavapipe)");
  sub->add_option("--trace", f->trace,
                  "Follow pixel X,Y through the pixel listing: each instruction's result on "
                  "each device of --backend, and the first instruction where they differ");
  set_action(sub, [f] { return run(*f); });
}

} // namespace tierlift::cli
