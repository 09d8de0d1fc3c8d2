// `tierlift glow --frames N` (setup apart from steady-state frames, in the table and the
// JSON) and the refusal of a scene that does not fit in memory (before anything is made).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_fixture.h"

namespace {

namespace fs = std::filesystem;

class CliGlowFrames : public tierlift::cli_test::CliFixture {
protected:
  fs::path scene(uint32_t w, uint32_t h) {
    const fs::path p = dir / "scene.json";
    std::ofstream(p) << "{\"size\": [" << w << ", " << h << "]}\n";
    return p;
  }
  // `tierlift glow` on a 16384² scene into dir/images, under the limit `prefix` sets.
  void expect_huge_scene_refused(const std::string& prefix);
};

TEST_F(CliGlowFrames, JsonReportsSetupAndSteadyFramesPerDevice) {
  std::string out, err;
  ASSERT_EQ(
      run("glow --scene " + scene(64, 32).string() + " --backend cpu --frames 3 --json", out, err),
      0)
      << err;
  const nlohmann::json j = nlohmann::json::parse(out)["result"]; // docs/command-line.md
  ASSERT_TRUE(j.contains("frames")) << out;
  const nlohmann::json& f = j["frames"]["cpu"];
  EXPECT_EQ(f["n"], 3);
  for (const char* k : {"setup_ms", "median_ms", "min_ms", "max_ms"})
    ASSERT_TRUE(f[k].is_number()) << k;
  EXPECT_LE(f["min_ms"].get<double>(), f["median_ms"].get<double>());
  EXPECT_LE(f["median_ms"].get<double>(), f["max_ms"].get<double>());
  EXPECT_FALSE(j["frames"].contains("vulkan")); // only the devices that ran
}

TEST_F(CliGlowFrames, TableHasARowPerDevice) {
  std::string out, err;
  ASSERT_EQ(
      run("glow --scene " + scene(64, 32).string() + " --backend analytic --frames 2 -q", out, err),
      0)
      << err;
  EXPECT_NE(out.find("setup ms"), std::string::npos) << out;
  EXPECT_NE(out.find("\nanalytic "), std::string::npos) << out;
}

TEST_F(CliGlowFrames, FramesOutOfRangeIsAUsageError) {
  std::string out, err;
  EXPECT_EQ(run("glow --frames 0", out, err), 2) << err;
}

// 16384² RGBA32F: one host copy is 4 GiB, the three ways keep ~20 of them. Refused with the
// bytes needed and available and the knobs, exit 1, and nothing written. The budget is 16
// GiB either way, so the verdict is the same on any machine; the run needs far more.
void expect_refused(const std::string& out, const std::string& err, const fs::path& o, int rc) {
  EXPECT_EQ(rc, 1) << err;
  EXPECT_NE(err.find("tierlift glow: error: "), std::string::npos) << err;
  EXPECT_NE(err.find("scene.json: the glow at 16384x16384"), std::string::npos) << err;
  EXPECT_NE(err.find("needs"), std::string::npos) << err;
  EXPECT_NE(err.find("available"), std::string::npos) << err;
  for (const char* knob : {"--format", "--downsample", "--backend"})
    EXPECT_NE(err.find(knob), std::string::npos) << knob << ": " << err;
  EXPECT_FALSE(fs::exists(o));
  EXPECT_EQ(out, "");
}

void CliGlowFrames::expect_huge_scene_refused(const std::string& prefix) {
  std::string out, err;
  const fs::path o = dir / "images";
  const int rc =
      run("glow --scene " + scene(16384, 16384).string() + " -o " + o.string(), out, err, prefix);
  expect_refused(out, err, o, rc);
}

TEST_F(CliGlowFrames, SceneBeyondTheMemoryBudgetIsRefusedBeforeRunning) {
  expect_huge_scene_refused("TIERLIFT_MEMORY_LIMIT=17179869184 ");
}

#if !defined(__SANITIZE_ADDRESS__) // ASan's shadow memory cannot live under `ulimit -v`
TEST_F(CliGlowFrames, SceneBeyondTheAddressSpaceLimitIsRefusedBeforeRunning) {
  expect_huge_scene_refused("ulimit -v 16777216; ");
}
#endif

} // namespace
