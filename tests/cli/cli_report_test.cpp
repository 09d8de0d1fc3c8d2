// `tierlift report`: the files it writes (they exist and parse; the plot decodes, has the
// asked size and is not blank) and bad input (nothing in DIR, DIR absent).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_fixture.h"
#include "tierlift/image/io.h"

namespace {

namespace fs = std::filesystem;

class CliReport : public tierlift::cli_test::CliFixture {
protected:
  fs::path scene(const std::string& json) {
    const fs::path p = dir / "scene.json";
    std::ofstream(p) << json;
    return p;
  }
  // A small sweep over a small scene: two tiers, two formats, cpu + vulkan + analytic.
  std::string small_sweep() {
    return "report --scene " +
           scene("{\"size\": [48, 32], \"glow\": {\"profile\": {\"gaussians\": "
                 "[{\"sigma\": 3, \"weight\": 1}]}}}\n")
               .string() +
           " --downsamples 2 --taps 1 --formats rgba8,rgba32f --half-texel on --frames 1";
  }
  // Nothing but our own scene and captured output in the fixture's folder.
  std::set<std::string> leftovers() {
    std::set<std::string> names;
    for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
      const std::string n = e.path().filename().string();
      if (n != "scene.json" && n != "out.txt" && n != "err.txt") names.insert(n);
    }
    return names;
  }
};

TEST_F(CliReport, WritesEveryFileAndAPlotThatIsNotBlank) {
  std::string out, err;
  const fs::path rep = dir / "rep";
  ASSERT_EQ(run(small_sweep() + " -o " + rep.string(), out, err), 0) << err;
  EXPECT_NE(err.find("[report]"), std::string::npos) << "progress on stderr: " << err;
  for (const char* f :
       {"report.json", "report.csv", "report.md", "error-vs-time.png", "error-vs-time.svg"})
    ASSERT_TRUE(fs::is_regular_file(rep / f)) << f;
  const nlohmann::json j = nlohmann::json::parse(read(rep / "report.json"));
  const nlohmann::json& configs = j["configurations"];
  // Every tier × {rgba8, rgba32f}, the scene's own choice (dx9 rgba32f) among them.
  ASSERT_GE(configs.size(), 4u);
  EXPECT_TRUE(configs[0]["scene_choice"].get<bool>());
  for (const nlohmann::json& c : configs) {
    ASSERT_FALSE(c.contains("skipped")) << c.dump();
    EXPECT_TRUE(c["all_agree"].get<bool>()) << c.dump();
    EXPECT_TRUE(c["times"].contains("vulkan")) << c.dump();
    EXPECT_GT(c["error"]["final"]["rmse"].get<double>(), 0.0);
  }
  EXPECT_FALSE(j["pareto"].empty());
  // The CSV: a header and one row per configuration.
  const std::string csv = read(rep / "report.csv");
  EXPECT_EQ(size_t(std::count(csv.begin(), csv.end(), '\n')), configs.size() + 1);
  const std::string md = read(rep / "report.md");
  for (const char* part : {"## Pareto front", "## The scene's own configuration",
                           "## Cheapest within 1/255", "## What to pick"})
    EXPECT_NE(md.find(part), std::string::npos) << part;
  EXPECT_NE(read(rep / "error-vs-time.svg").find("<svg"), std::string::npos);
  // The PNG decodes, has the size asked for, and is not one colour.
  const tierlift::img::ImageResult png =
      tierlift::img::read_png((rep / "error-vs-time.png").string());
  ASSERT_TRUE(png) << png.message();
  EXPECT_EQ(png->width, 1000u);
  EXPECT_EQ(png->height, 700u);
  std::set<std::array<float, 3>> colours;
  for (size_t i = 0; i + 3 < png->rgba.size() && colours.size() < 8; i += 4)
    colours.insert({png->rgba[i], png->rgba[i + 1], png->rgba[i + 2]});
  EXPECT_GE(colours.size(), 8u);
  // Only the report's folder beside the scene: no temporary left.
  EXPECT_EQ(leftovers(), std::set<std::string>{"rep"});
}

TEST_F(CliReport, BadInputLeavesTheFolderAbsent) {
  std::string out, err;
  const fs::path rep = dir / "rep";
  // An unreadable scene: exit 2, the file named.
  EXPECT_EQ(run("report --scene " + (dir / "none.json").string() + " -o " + rep.string(), out, err),
            2);
  EXPECT_NE(err.find("none.json"), std::string::npos) << err;
  // A scene with an error: the positioned diagnostic.
  EXPECT_EQ(run("report --scene " + scene("{\n  \"glow\": {\"downsample\": 9}\n}\n").string() +
                    " -o " + rep.string(),
                out, err),
            1);
  EXPECT_NE(err.find("scene.json:2:"), std::string::npos) << err;
  EXPECT_NE(err.find("^"), std::string::npos) << err;
  // An empty sweep and a word that is not a choice: usage errors.
  EXPECT_EQ(run("report --formats , -o " + rep.string(), out, err), 2);
  EXPECT_NE(err.find("sweep is empty"), std::string::npos) << err;
  EXPECT_EQ(run("report --tiers dx11 -o " + rep.string(), out, err), 2);
  EXPECT_NE(err.find("dx11"), std::string::npos) << err;
  // gnuplot missing: said so, with the package that brings it, and nothing written.
  EXPECT_EQ(run(small_sweep() + " --tiers dx9 --formats rgba8 --no-vulkan -o " + rep.string(), out,
                err, "TIERLIFT_GNUPLOT=/nonexistent/gnuplot "),
            2);
  EXPECT_NE(err.find("gnuplot-nox"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(rep));
  EXPECT_TRUE(leftovers().empty());
}

TEST_F(CliReport, CaseNeedsStressAndGnuplotIsLookedForBeforeTheSweep) {
  std::string out, err;
  // --case alone used to start the whole sweep and ignore it: a usage error now.
  EXPECT_EQ(run("report --case dx9-nan-source", out, err), 2);
  EXPECT_NE(err.find("needs --stress"), std::string::npos) << err;
  EXPECT_EQ(err.find("[report]"), std::string::npos) << err;
  // gnuplot missing: refused before the first configuration runs (no progress line).
  const fs::path rep = dir / "rep";
  EXPECT_EQ(run(small_sweep() + " --tiers dx9 --formats rgba8 --no-vulkan -o " + rep.string(), out,
                err, "TIERLIFT_GNUPLOT=/nonexistent/gnuplot "),
            2);
  EXPECT_NE(err.find("gnuplot-nox"), std::string::npos) << err;
  EXPECT_EQ(err.find("[report]"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(rep));
}

TEST_F(CliReport, JsonIsOneDocument) {
  std::string out, err;
  ASSERT_EQ(run(small_sweep() + " --tiers dx8 --formats rgba8 --json", out, err), 0) << err;
  EXPECT_TRUE(err.empty()) << err;
  const nlohmann::json j = nlohmann::json::parse(out);
  EXPECT_EQ(j["command"], "report");
  EXPECT_TRUE(j["ok"].get<bool>());
  EXPECT_FALSE(j["result"]["configurations"].empty());
}

} // namespace
