// tests/corpus/bgfx: 175 real vs_3_0/ps_3_0 shaders (fxc outputs shipped by bgfx; the folder's
// README says where from and under which licence). Each runs through the whole lift as
// `tierlift test tests/corpus/bgfx` runs it (parse, validate, round trip, SPIR-V, and the
// interpreter against Vulkan on generated inputs), and must pass, except the shaders listed
// below with the reason each does not yet. A listed shader that starts to pass is fine (the
// reason went away); one that fails for another reason, or an unlisted one that fails, is a
// regression. So is a pass count below the one measured when the folder was added.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "skip_policy.h"
#include "tierlift/corpus/cases.h"
#include "tierlift/corpus/stages.h"
#include "tierlift/vulkan/process_device.h"

namespace tierlift::corpus {
namespace {

namespace fs = std::filesystem;

const fs::path kBgfx = fs::path(TIERLIFT_SOURCE_DIR) / "tests" / "corpus" / "bgfx";

// file -> what its first stage that does not pass says (a part of it). Empty: every shader
// passes (the last two, vs_rsm_lbuffer and vs_terrain_height_texture, since vertex texture
// fetch runs, NUMERICS.md F14); a shader that fails now fails the test.
const std::map<std::string, std::string> kExceptions = {};

constexpr size_t kFiles = 175;
// 148 when the folder was added; 172 since a ps_3_0 reads fog0 (NUMERICS.md F6); 173 since
// the interpreter's sine is lavapipe's (rule 39: fs_sky_landscape's frc(sin(x)·43758.5));
// 175, all of them, since vs_3_0's texldl reads the vertex samplers (F14).
constexpr size_t kMeasuredPasses = 175;

// The message of the first stage that did not pass, with the stage's name.
std::string first_problem(const CaseResult& r) {
  for (const StageResult& s : r.stages)
    if (s.verdict != Verdict::Pass && s.verdict != Verdict::Skip) return s.stage + ": " + s.message;
  return "";
}

TEST(BgfxCorpus, EveryShaderRunsOnBothDevicesAndAgreesButTheListedOnes) {
  ir::Result<vulkan::Device*> device = vulkan::process_device({});
  if (!device) TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device");
  ir::Result<std::vector<Case>> cases = discover({kBgfx.string()});
  ASSERT_TRUE(cases) << cases.message();
  ASSERT_EQ(cases->size(), kFiles);
  StageOptions options; // `tierlift test`'s defaults: 3 input sets, seed 1, 8 x 8
  options.device = *device;
  size_t passes = 0;
  for (const Case& c : *cases) {
    const std::string file = fs::path(c.path).filename().string();
    const CaseResult r = run_case(c, options);
    if (r.verdict == Verdict::Pass) {
      ++passes;
      continue;
    }
    const auto listed = kExceptions.find(file);
    if (listed == kExceptions.end()) {
      ADD_FAILURE() << file << " does not pass: " << first_problem(r);
      continue;
    }
    EXPECT_NE(first_problem(r).find(listed->second), std::string::npos)
        << file << " fails for another reason than \"" << listed->second
        << "\": " << first_problem(r);
  }
  std::printf("[bgfx-corpus] %zu of %zu shaders run on both devices and agree\n", passes,
              cases->size());
  EXPECT_GE(passes, kMeasuredPasses);
}

} // namespace
} // namespace tierlift::corpus
