// The report's files (report_files.h): JSON, CSV and Markdown text, the gnuplot plot, and
// moving them into place.
#include "tierlift/effects/report/report_files.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

namespace tierlift::effects {
namespace fs = std::filesystem;

namespace {

const char* const kDevices[] = {"cpu", "vulkan", "analytic"};

const DeviceTime* time_of(const ConfigResult& c, std::string_view device) {
  for (const DeviceTime& t : c.times)
    if (t.device == device) return &t;
  return nullptr;
}

nlohmann::json error_json(const IdealError& e) {
  return {{"max_abs", e.max_abs}, {"rmse", e.rmse}, {"share_off_1_255", e.share_off}};
}

std::string series_name(Tier t, img::Format f) {
  return fmt::format("{} {}", tier_name(t), img::format_name(f));
}

// Errors of 0 have no place on a log axis: drawn at this floor (said in the key).
constexpr double kLogFloor = 1e-9;

bool on_front(const SweepResult& r, size_t i) {
  return std::find(r.pareto.begin(), r.pareto.end(), i) != r.pareto.end();
}

std::string write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) return fmt::format("{}: cannot write", path.string());
  return {};
}

// The data file (one block per tier × format, then the front, then the scene's choice) and
// the script that draws the PNG and the SVG from it.
std::string plot_files(const SweepResult& r, const ReportInfo& info, const fs::path& tmp,
                       std::string* script) {
  std::vector<std::pair<Tier, img::Format>> series;
  for (const ConfigResult& c : r.configs)
    if (c.skipped.empty() && !c.times.empty()) {
      const std::pair<Tier, img::Format> k{c.config.tier, c.config.format};
      if (std::find(series.begin(), series.end(), k) == series.end()) series.push_back(k);
    }
  if (series.empty()) return "no configuration ran: nothing to plot";
  auto point = [](const ConfigResult& c) {
    return fmt::format("{:.9g} {:.9g}\n", c.frame_ms(), std::max(c.final.rmse, kLogFloor));
  };
  std::string data;
  for (const auto& [tier, format] : series) {
    data += fmt::format("# {}\n", series_name(tier, format));
    for (const ConfigResult& c : r.configs)
      if (c.skipped.empty() && !c.times.empty() && c.config.tier == tier &&
          c.config.format == format)
        data += point(c);
    data += "\n\n";
  }
  data += "# Pareto front\n";
  for (size_t i : r.pareto) data += point(r.configs[i]);
  data += "\n\n# the scene's choice\n";
  bool own = false;
  for (const ConfigResult& c : r.configs)
    if (c.scene_choice && c.skipped.empty() && !c.times.empty()) data += point(c), own = true;
  if (!own) data += "nan nan\n";
  const fs::path data_path = tmp / "plot.dat";
  if (std::string e = write_text(data_path, data); !e.empty()) return e;

  // Marker shape per tier, colour per format: every tier × format has its own style.
  auto shape = [](Tier t) { return 5 + 2 * int(t); }; // 5 square, 7 circle, 9 triangle, …
  auto colour = [](img::Format f) {
    return f == img::Format::RGBA8 ? "#1b9e77" : f == img::Format::RGBA16F ? "#7570b3" : "#d95f02";
  };
  std::string plot = "plot ";
  for (size_t i = 0; i < series.size(); ++i)
    plot += fmt::format("'{}' index {} using 1:2 with points pt {} ps 1.4 lc rgb '{}' title '{}', ",
                        data_path.string(), i, shape(series[i].first), colour(series[i].second),
                        series_name(series[i].first, series[i].second));
  plot += fmt::format("'{}' index {} using 1:2 with lines dt 2 lw 1.5 lc rgb 'black' title "
                      "'Pareto front', ",
                      data_path.string(), series.size());
  plot += fmt::format("'{}' index {} using 1:2 with points pt 6 ps 3.5 lw 2.5 lc rgb 'red' title "
                      "'the scene''s choice', ",
                      data_path.string(), series.size() + 1);
  plot += "1.0/255 with lines dt 3 lc rgb 'gray40' title '1/255'\n";
  const std::string common =
      fmt::format("set logscale xy\nset grid\nset key outside right top\n"
                  "set title 'glow error against frame time ({}x{}, intensity {})'\n"
                  "set xlabel 'frame time, ms ({} median)'\n"
                  "set ylabel 'final frame RMSE against the ideal glow (0 drawn at {:g})'\n",
                  info.width, info.height, info.intensity,
                  info.vulkan_device.empty() ? "cpu" : "vulkan", kLogFloor);
  *script =
      fmt::format("set terminal pngcairo size {},{} font 'sans,10'\nset output '{}'\n{}{}"
                  "set terminal svg size {},{} font 'sans,10'\nset output '{}'\nreplot\n",
                  info.plot_width, info.plot_height, (tmp / "error-vs-time.png").string(), common,
                  plot, info.plot_width, info.plot_height, (tmp / "error-vs-time.svg").string());
  return write_text(tmp / "plot.gp", *script);
}

// Runs gnuplot on the script; its output goes to a log beside it, quoted on failure.
std::string run_gnuplot(const fs::path& tmp) {
  const std::string program = gnuplot_program();
  const std::string script = (tmp / "plot.gp").string(), log = (tmp / "gnuplot.log").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  std::vector<char*> argv = {const_cast<char*>(program.c_str()), const_cast<char*>(script.c_str()),
                             nullptr};
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    return fmt::format("cannot run {} to draw the plot: {}{}", program, std::strerror(rc),
                       rc == ENOENT ? " (install the Debian package gnuplot-nox; "
                                      "scripts/install-deps.sh does)"
                                    : "");
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return fmt::format("waiting for {}: {}", program, std::strerror(errno));
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
  std::ifstream in(log);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.size() > 2000) text = text.substr(0, 2000) + "…";
  return fmt::format("{} failed ({}): {}", program,
                     WIFEXITED(status) ? fmt::format("exit {}", WEXITSTATUS(status))
                                       : std::string("killed by a signal"),
                     text);
}

} // namespace

std::string gnuplot_program() {
  const char* env = std::getenv("TIERLIFT_GNUPLOT");
  return env && *env ? env : "gnuplot";
}

ir::Status check_gnuplot() {
  const std::string program = gnuplot_program();
  auto runnable = [](const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
           ::access(path.c_str(), X_OK) == 0;
  };
  bool found = false;
  if (program.find('/') != std::string::npos) {
    found = runnable(program);
  } else if (const char* path = std::getenv("PATH")) {
    std::string_view dirs = path;
    while (!found) {
      const size_t colon = dirs.find(':');
      const std::string dir(dirs.substr(0, colon));
      found = runnable((dir.empty() ? std::string(".") : dir) + "/" + program);
      if (colon == std::string_view::npos) break;
      dirs.remove_prefix(colon + 1);
    }
  }
  if (found) return ir::ok_status();
  return ir::fail("gnuplot", "io",
                  fmt::format("cannot find {} to draw the plot (install the Debian package "
                              "gnuplot-nox; scripts/install-deps.sh does; TIERLIFT_GNUPLOT names "
                              "another program)",
                              program));
}

nlohmann::json report_json(const SweepResult& r, const SweepSettings& s, const ReportInfo& info) {
  nlohmann::json tiers = nlohmann::json::array(), formats = nlohmann::json::array();
  for (Tier t : s.tiers) tiers.push_back(tier_name(t));
  for (img::Format f : s.formats) formats.push_back(img::format_name(f));
  nlohmann::json j = {
      {"scene",
       {{"file", info.scene_file},
        {"image", info.scene_image},
        {"width", info.width},
        {"height", info.height},
        {"intensity", info.intensity}}},
      {"vulkan_device", info.vulkan_device},
      {"sweep",
       {{"quick", s.quick},
        {"tiers", tiers},
        {"downsamples", s.downsamples},
        {"taps_radius_fractions", s.taps},
        {"formats", formats},
        {"half_texel", s.half_texels},
        {"frames", s.frames},
        {"timed_devices", s.timed}}},
      {"error_metric", "final frame RMSE against the ideal glow (scene + intensity x ideal glow), "
                       "both as displayed: clamped to [0, 1]"},
      {"frame_time", "median steady-state frame, vulkan (cpu when vulkan did not run)"}};
  nlohmann::json configs = nlohmann::json::array();
  for (size_t i = 0; i < r.configs.size(); ++i) {
    const ConfigResult& c = r.configs[i];
    nlohmann::json o = {{"tier", tier_name(c.config.tier)},
                        {"downsample", c.config.downsample},
                        {"taps", c.config.taps},
                        {"format", img::format_name(c.config.format)},
                        {"half_texel", c.config.half_texel},
                        {"scene_choice", c.scene_choice}};
    if (!c.skipped.empty()) {
      o["skipped"] = c.skipped;
      configs.push_back(o);
      continue;
    }
    o["passes"] = c.passes;
    o["glow_size"] = {c.glow_width, c.glow_height};
    o["error"] = {{"glow", error_json(c.glow)}, {"final", error_json(c.final)}};
    nlohmann::json agree = nlohmann::json::array();
    for (const PairResult& p : c.agreement)
      agree.push_back({{"a", p.a},
                       {"b", p.b},
                       {"within_targets", p.within},
                       {"frame_max_abs", p.frame_max_abs}});
    o["agreement"] = agree;
    o["all_agree"] = c.all_agree;
    nlohmann::json times = nlohmann::json::object();
    for (const DeviceTime& t : c.times)
      times[t.device] = {{"setup_ms", t.setup_ms},
                         {"median_ms", t.median_ms},
                         {"min_ms", t.min_ms},
                         {"max_ms", t.max_ms},
                         {"n", t.frames}};
    o["times"] = times;
    o["frame_ms"] = c.frame_ms();
    o["pruning"] = {{"left_out_passes", c.pruned_left_out},
                    {"limited_pass_groups", c.pruned_limited},
                    {"frame_ms", c.pruned_frame_ms}};
    o["pareto"] = on_front(r, i);
    configs.push_back(o);
  }
  j["configurations"] = configs;
  j["pareto"] = r.pareto;
  j["pareto_error_tolerance"] = {{"relative", kParetoRelativeTolerance},
                                 {"absolute", kParetoAbsoluteTolerance}};
  j["cheapest_within_1_255"] =
      r.cheapest_within ? nlohmann::json(*r.cheapest_within) : nlohmann::json(nullptr);
  return j;
}

std::string report_csv(const SweepResult& r) {
  std::string out = "scene_choice,tier,downsample,taps,format,half_texel,passes,skipped,"
                    "glow_max_abs,glow_rmse,glow_share_off,final_max_abs,final_rmse,"
                    "final_share_off,all_agree";
  for (const char* d : kDevices) out += fmt::format(",{0}_setup_ms,{0}_median_ms", d);
  out += ",frame_ms,pareto,pruned_left_out,pruned_limited,pruned_frame_ms\n";
  for (size_t i = 0; i < r.configs.size(); ++i) {
    const ConfigResult& c = r.configs[i];
    std::string skipped = c.skipped;
    std::replace(skipped.begin(), skipped.end(), '"', '\'');
    out +=
        fmt::format("{},{},{},{},{},{},{},\"{}\"", c.scene_choice ? 1 : 0, tier_name(c.config.tier),
                    c.config.downsample, c.config.taps, img::format_name(c.config.format),
                    c.config.half_texel ? 1 : 0, c.passes, skipped);
    if (!c.skipped.empty()) {
      out += std::string(7 + 2 * std::size(kDevices) + 5, ',') + "\n";
      continue;
    }
    out += fmt::format(",{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{}", c.glow.max_abs, c.glow.rmse,
                       c.glow.share_off, c.final.max_abs, c.final.rmse, c.final.share_off,
                       c.all_agree ? 1 : 0);
    for (const char* d : kDevices) {
      const DeviceTime* t = time_of(c, d);
      out += t ? fmt::format(",{:.3f},{:.3f}", t->setup_ms, t->median_ms) : std::string(",,");
    }
    out += fmt::format(",{:.3f},{},{},{},{:.3f}\n", c.frame_ms(), on_front(r, i) ? 1 : 0,
                       c.pruned_left_out, c.pruned_limited, c.pruned_frame_ms);
  }
  return out;
}

std::string report_markdown(const SweepResult& r, const SweepSettings& s, const ReportInfo& info) {
  const char* clock = info.vulkan_device.empty() ? "cpu" : "vulkan";
  std::string md = fmt::format(
      "# Glow error against run time\n\n"
      "Scene: {} ({}x{}, intensity {}). Sweep: {} ({} configurations), {} steady-state "
      "frame(s) timed on {}. Error: the final frame's RMSE against the ideal glow (the "
      "glow sources convolved with the profile's continuous kernel at full resolution, in "
      "double), both as a display shows them (clamped to [0, 1]); the glow columns measure "
      "the glow itself, unclamped. Frame time: the {} median{}.\n\n",
      info.scene_file.empty() ? info.scene_image : info.scene_file, info.width, info.height,
      info.intensity, s.quick ? "quick" : "full", r.configs.size(), s.frames,
      fmt::join(s.timed, ", "), clock,
      info.vulkan_device.empty() ? "" : fmt::format(" ({})", info.vulkan_device));
  auto row = [&](size_t i) {
    const ConfigResult& c = r.configs[i];
    return fmt::format("| {} | {:.2f} | {:.3g} | {:.3g} | {:.3g} | {:.2f} % | {} |\n",
                       config_label(c.config), c.frame_ms(), c.final.rmse, c.final.max_abs,
                       c.glow.rmse, 100 * c.final.share_off, c.all_agree ? "yes" : "NO");
  };
  const std::string head =
      "| configuration | frame ms | final RMSE | final max abs | glow RMSE | pixels off > "
      "1/255 | ways agree |\n| --- | ---: | ---: | ---: | ---: | ---: | --- |\n";
  md += fmt::format("## Pareto front\n\nNo other configuration is both faster and closer to the "
                    "ideal. Final RMSEs within {:g} of the larger one, or within {:g}, count as "
                    "equal: the faster of two such configurations is kept.\n\n",
                    kParetoRelativeTolerance, kParetoAbsoluteTolerance) +
        head;
  for (size_t i : r.pareto) md += row(i);
  md += "\n## The scene's own configuration\n\n";
  std::optional<size_t> own;
  for (size_t i = 0; i < r.configs.size(); ++i)
    if (r.configs[i].scene_choice) own = i;
  if (!own || !r.configs[*own].skipped.empty()) {
    md += own ? fmt::format("Not run: {}\n", r.configs[*own].skipped) : "Not in the sweep.\n";
  } else {
    const ConfigResult& c = r.configs[*own];
    size_t faster = 0, closer = 0, ran = 0;
    for (const ConfigResult& o : r.configs)
      if (o.skipped.empty() && !o.times.empty()) {
        ++ran;
        faster += o.frame_ms() < c.frame_ms();
        closer += o.final.rmse < c.final.rmse;
      }
    md += head + row(*own) + "\n";
    md += fmt::format("{} of {} configurations are faster and {} are closer to the ideal; it {} "
                      "on the Pareto front.\n",
                      faster, ran, closer, on_front(r, *own) ? "lies" : "does not lie");
    if (!on_front(r, *own))
      for (size_t i : r.pareto)
        if (r.configs[i].frame_ms() <= c.frame_ms() && r.configs[i].final.rmse <= c.final.rmse) {
          md += fmt::format("`{}` is at least as fast and at least as close.\n",
                            config_label(r.configs[i].config));
          break;
        }
  }
  md += "\n## Leaving out what the scene does not need\n\n"
        "Frame time of the whole plan and of the plan pruned for this scene (`tierlift glow "
        "--explain` lists what is left out and why), for every configuration where pruning "
        "leaves something out or limits passes to the sources' box:\n\n| configuration | "
        "passes left out | pass groups limited | whole plan ms | pruned ms |\n| --- | ---: | "
        "---: | ---: | ---: |\n";
  size_t pruned_rows = 0;
  for (const ConfigResult& c : r.configs)
    if (c.skipped.empty() && (c.pruned_left_out > 0 || c.pruned_limited > 0)) {
      md += fmt::format("| {} | {} | {} | {:.2f} | {:.2f} |\n", config_label(c.config),
                        c.pruned_left_out, c.pruned_limited, c.frame_ms(), c.pruned_frame_ms);
      ++pruned_rows;
    }
  if (pruned_rows == 0)
    md += "| (none: this scene needs every pass of every configuration) | | | | |\n";
  md += "\n## Cheapest within 1/255 of the ideal\n\n";
  if (r.cheapest_within)
    md += head + row(*r.cheapest_within) +
          "\nThe fastest configuration whose final-frame RMSE against the ideal is at most "
          "1/255.\n";
  else
    md += "No configuration comes within 1/255 (final-frame RMSE) of the ideal.\n";
  md += "\n## What to pick\n\n";
  if (r.cheapest_within)
    md += fmt::format("For this scene's look, `{}`: the cheapest configuration that a viewer "
                      "cannot tell from the ideal on average (RMSE ≤ 1/255).\n",
                      config_label(r.configs[*r.cheapest_within].config));
  else if (!r.pareto.empty())
    md += fmt::format("For this scene's look, `{}`: the Pareto configuration closest to the "
                      "ideal.\n",
                      config_label(r.configs[r.pareto.back()].config));
  size_t skipped = 0, disagree = 0;
  for (const ConfigResult& c : r.configs) {
    skipped += !c.skipped.empty();
    disagree += c.skipped.empty() && !c.all_agree;
  }
  md += fmt::format("\n{} configuration(s) skipped (reasons in report.json); {} where the ways "
                    "differ beyond docs/design.md's targets.\n\n"
                    "![error against frame time](error-vs-time.png)\n",
                    skipped, disagree);
  return md;
}

namespace {

// write_report's work; empty on success, else why (the caller's folder, never committed,
// then removes what was written).
std::string write_report_files(io::OutputFolder& out, const SweepResult& r, const SweepSettings& s,
                               const ReportInfo& info, std::vector<std::string>* written) {
  std::vector<std::string> paths;
  for (const std::string& name : report_file_names()) {
    ir::Result<std::string> path = out.path(name);
    if (!path) return path.message();
    paths.push_back(*path);
  }
  const fs::path tmp = out.temp_dir(); // gnuplot's data, script and log: scratch beside them
  const std::string texts[] = {report_json(r, s, info).dump(2) + "\n", report_csv(r),
                               report_markdown(r, s, info)};
  for (size_t i = 0; i < std::size(texts); ++i)
    if (std::string e = write_text(paths[i], texts[i]); !e.empty()) return e;
  std::string script;
  if (std::string e = plot_files(r, info, tmp, &script); !e.empty()) return e;
  if (std::string e = run_gnuplot(tmp); !e.empty()) return e;
  std::error_code ec;
  for (const char* name : {"plot.dat", "plot.gp", "gnuplot.log"}) fs::remove(tmp / name, ec);
  for (const std::string& path : paths)
    if (!fs::is_regular_file(path, ec))
      return fmt::format("{} did not write {}", gnuplot_program(),
                         fs::path(path).filename().string());
  ir::Result<std::vector<std::string>> done = out.commit();
  if (!done) return done.message();
  if (written) *written = std::move(done).value();
  return {};
}

} // namespace

const std::vector<std::string>& report_file_names() {
  static const std::vector<std::string> names = {"report.json", "report.csv", "report.md",
                                                 "error-vs-time.png", "error-vs-time.svg"};
  return names;
}

ir::Result<std::vector<std::string>> write_report(io::OutputFolder& out, const SweepResult& r,
                                                  const SweepSettings& s, const ReportInfo& info) {
  std::vector<std::string> written;
  if (std::string e = write_report_files(out, r, s, info, &written); !e.empty())
    return ir::fail(out.dir(), "io", std::move(e));
  return written;
}

} // namespace tierlift::effects
