// tierlift generate --profile P --seed S -n N -o DIR: N random valid listings (the generator
// of docs/generate.md), one file each, and what they cover.
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
#include "report.h"
#include "tierlift/generate/generate.h"
#include "tierlift/ir/profile.h"

namespace tierlift::cli {
namespace {

struct GenerateOpts {
  std::string profile, output;
  std::uint64_t seed = 1;
  std::size_t count = 1, first = 0;
  bool coverage = false, json = false;
};

// "ps_2_0-s1-000042.psh": profile, seed and index name the listing (vertex listings .vsh).
std::string file_name(const GenerateOpts& o, ir::Profile p, std::size_t index) {
  return fmt::format("{}-s{}-{:06}.{}", ir::profile_name(p), o.seed, index,
                     ir::is_vertex(p) ? "vsh" : "psh");
}

int run_generate(const GenerateOpts& o) {
  Report report("generate", o.json);
  const ir::Result<ir::Profile> profile = gen::generated_profile(o.profile);
  if (!profile) {
    report.error("usage", profile.message());
    return report.finish(kExitUsage);
  }
  std::error_code ec;
  std::filesystem::create_directories(o.output, ec);
  if (!std::filesystem::is_directory(o.output)) {
    report.error("io", "cannot create the output folder", o.output);
    return report.finish(kExitUsage);
  }
  gen::Coverage coverage;
  nlohmann::json files = nlohmann::json::array();
  for (std::size_t i = o.first; i < o.first + o.count; ++i) {
    ir::Result<std::string> listing = gen::generate_listing(o.profile, o.seed, i);
    if (!listing) { // not expected: the profile was checked above
      report.error("usage", listing.message());
      return report.finish(kExitUsage);
    }
    const std::string& text = *listing;
    const std::string path = (std::filesystem::path(o.output) / file_name(o, *profile, i)).string();
    if (std::string error = write_output(path, text); !error.empty()) {
      report.error("io", error, path);
      return report.finish(kExitUsage);
    }
    if (o.coverage) coverage.add(text);
    files.push_back(path);
  }
  report.result()["files"] = files;
  if (o.coverage) {
    report.output("coverage", coverage.summary());
    report.result()["opcodes"] = coverage.opcodes.size();
  }
  return report.finish(kExitOk);
}

} // namespace

void register_generate_command(CLI::App& app) {
  auto opts = std::make_shared<GenerateOpts>();
  CLI::App* sub =
      app.add_subcommand("generate", "Write random valid listings of a profile (docs/generate.md)");
  sub->add_option("--profile", opts->profile, "Profile: " + gen::generated_profile_names())
      ->required();
  sub->add_option("--seed", opts->seed, "Seed; a listing depends on (profile, seed, index) only")
      ->capture_default_str();
  sub->add_option("-n,--count", opts->count, "How many listings")->capture_default_str();
  sub->add_option("--first", opts->first, "Index of the first listing")->capture_default_str();
  sub->add_option("-o,--output", opts->output, "Folder the listings are written to (created)")
      ->required();
  sub->add_flag("--coverage", opts->coverage,
                "Print the opcodes, modifiers, register files, swizzles and masks they use");
  sub->add_flag("--json", opts->json, "One JSON document on standard output");
  set_action(sub, [opts] { return run_generate(*opts); });
}

} // namespace tierlift::cli
