// tierlift report --stress: the stress catalogue (tierlift::effects, stress.h) on the
// interpreter, on Vulkan and as analytic math, printed as a table of measured against
// expected with a verdict per row; --json prints the rows as JSON, -o DIR writes
// DIR/stress.json and DIR/stress.md. Only flags and printing live here.
// cmd_report.cpp registers the command and hands --stress here.
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "cmd_stress.h"
#include "commands.h"
#include "front_end.h"
#include "report.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/graph/vulkan_device.h"
#include "tierlift/effects/report/stress.h"
#include "tierlift/io/output_folder.h"

namespace tierlift::cli {
namespace {

// A number as JSON: NaN and infinities as strings (JSON has no such numbers).
nlohmann::json number_json(double v) {
  if (std::isfinite(v)) return v;
  return effects::stress_number(v);
}

nlohmann::json rows_json(const std::vector<effects::StressRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const effects::StressRow& r : rows) {
    nlohmann::json measured = nlohmann::json::object();
    for (const effects::StressMeasure& m : r.measured) measured[m.way] = number_json(m.value);
    nlohmann::json also = nlohmann::json::object();
    for (const auto& [way, v] : r.also_expected) also[way] = number_json(v);
    out.push_back({{"id", r.id},
                   {"regime", r.regime},
                   {"format", r.format},
                   {"quantity", r.quantity},
                   {"expected", number_json(r.expected)},
                   {"tolerance", number_json(r.tolerance)},
                   {"also_expected", also},
                   {"ideal", r.has_ideal ? number_json(r.ideal) : nlohmann::json()},
                   {"bound", r.bound},
                   {"measured", measured},
                   {"ways_agree", r.ways_agree},
                   {"verdict", r.verdict},
                   {"note", r.note},
                   {"error", r.error}});
  }
  return out;
}

} // namespace

int run_stress(const StressFlags& f) {
  Report report("report", f.json);
  if (f.output == "-") {
    report.error("usage", "-o names a folder for report --stress (stress.json, stress.md)");
    return report.finish(kExitUsage);
  }
  // -o DIR: whole at the end or as it was (io/output_folder.h); a bad DIR is said at once.
  std::optional<io::OutputFolder> out_dir;
  if (!f.output.empty()) {
    out_dir.emplace(f.output, std::vector<std::string>{}, "stress");
    if (ir::Status st = out_dir->status(); !st) {
      report.error("io", st.message(), f.output);
      return report.finish(kExitUsage);
    }
  }
  // The process's device, kept until exit as in `tierlift glow` (tests/lsan.supp).
  const ir::Result<vulkan::Device*> device = effects::vulkan_device(f.gpu);
  if (!device) {
    report.error("device", device.message());
    return report.finish(kExitUsage);
  }
  vulkan::Device* vk = *device;
  effects::StressOptions o;
  o.make_device = [vk](const std::string& way) -> std::unique_ptr<effects::PassDevice> {
    if (way == "cpu") return std::make_unique<effects::CpuPassDevice>();
    if (way == "vulkan") return effects::make_vulkan_pass_device(*vk);
    if (way == "analytic") return effects::make_analytic_pass_device();
    return nullptr;
  };
  const bool progress = !f.quiet && !f.json;
  o.progress = [progress](const std::string& id, size_t i, size_t n) {
    if (progress) fmt::print(stderr, "[stress {}/{}] {}\n", i + 1, n, id);
  };
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<effects::StressRow> rows;
  if (f.only.empty()) {
    rows = effects::run_stress_catalogue(o);
  } else {
    ir::Result<std::vector<effects::StressRow>> only = effects::run_stress_case(f.only, o);
    if (only) rows = std::move(only).value();
    if (rows.empty()) {
      report.error("usage", fmt::format("--case {}: {} (see --list)", f.only, only.message()));
      return report.finish(kExitUsage);
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  bool all_pass = true;
  for (const effects::StressRow& r : rows) all_pass = all_pass && r.verdict == "PASS";
  const nlohmann::json j = {{"rows", rows_json(rows)},
                            {"all_pass", all_pass},
                            {"seconds", seconds},
                            {"vulkan_device", effects::vulkan_device_name(*vk)}};
  std::vector<std::string> written;
  if (out_dir) {
    const std::string md =
        fmt::format("# tierlift report --stress\n\nVulkan device: {}; {:.1f} s\n\n{}",
                    effects::vulkan_device_name(*vk), seconds, effects::stress_table(rows, true));
    for (const auto& [name, text] :
         {std::pair<std::string, std::string>{"stress.json", j.dump(2) + "\n"},
          {"stress.md", md}}) {
      ir::Result<std::string> path = out_dir->path(name);
      std::string err = path ? write_output(*path, text) : path.message();
      if (!err.empty()) {
        report.error("io", err, f.output);
        return report.finish(kExitUsage);
      }
    }
    ir::Result<std::vector<std::string>> done = out_dir->commit();
    if (!done) {
      report.error("io", done.message(), f.output);
      return report.finish(kExitUsage);
    }
    written = std::move(done).value();
  }
  if (report.json()) {
    report.result() = j;
    report.result()["written"] = written;
  } else {
    fmt::print("{}", effects::stress_table(rows, false));
    fmt::print("{:.1f} s on cpu, vulkan ({}) and analytic\n", seconds,
               effects::vulkan_device_name(*vk));
    for (const std::string& w : written) fmt::print("wrote {}\n", w);
  }
  if (!all_pass) report.error("stress", "a stress row is not PASS (see its verdict)");
  return report.finish(all_pass ? kExitOk : kExitInvalid);
}

void add_stress_flags(CLI::App* sub, StressFlags& f) {
  sub->add_flag("--stress", f.stress,
                "Run the stress catalogue (docs/stress.md) instead of the sweep");
  sub->add_option("--case", f.only,
                  "With --stress: run one case of the catalogue (an id --list prints)");
  sub->add_flag_callback(
      "--list",
      [] {
        for (const std::string& id : effects::stress_case_ids()) fmt::print("{}\n", id);
        std::exit(kExitOk);
      },
      "Print the stress catalogue's case ids and exit");
}

} // namespace tierlift::cli
