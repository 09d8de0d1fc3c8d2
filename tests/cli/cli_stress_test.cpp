// `tierlift report --stress` end to end: one case through the CLI (JSON, files, exit code),
// and the usage errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "cli_fixture.h"
#include "skip_policy.h"

namespace {

namespace fs = std::filesystem;

class CliStress : public tierlift::cli_test::CliFixture {};

TEST_F(CliStress, OneCaseWritesJsonAndMarkdown) {
  const fs::path log = dir / "out.json";
  const int rc = run_cli("report --stress --case weights --json -o " + (dir / "r").string(), log);
  if (rc == 2 && read(log).find("\"device\"") != std::string::npos)
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device");
  ASSERT_EQ(rc, 0) << read(log);
  const nlohmann::json j = nlohmann::json::parse(read(log));
  const nlohmann::json& rows = j["result"]["rows"];
  ASSERT_EQ(rows.size(), 2u);
  // The seed's kernel: nine weights summing to 0.98, two axes: 0.9604 (closed form here).
  for (const nlohmann::json& r : rows)
    if (r["id"] == "weights.glsl-0.98") {
      EXPECT_NEAR(r["expected"].get<double>(), 0.98 * 0.98, 1e-7); // fp32 weights
      for (const char* way : {"cpu", "vulkan", "analytic"})
        EXPECT_NEAR(r["measured"][way].get<double>(), 0.9604, 1e-5) << way;
      EXPECT_EQ(r["verdict"], "PASS");
    }
  EXPECT_TRUE(fs::exists(dir / "r" / "stress.json"));
  EXPECT_NE(read(dir / "r" / "stress.md").find("| weights.glsl-0.98 |"), std::string::npos);
}

TEST_F(CliStress, UsageErrors) {
  const fs::path log = dir / "log.txt";
  EXPECT_EQ(run_cli("report --stress --quick", log), 2);     // the catalogue is its own sweep
  EXPECT_EQ(run_cli("report --stress --case nope", log), 2); // unknown case
  EXPECT_EQ(run_cli("report --stress -o -", log), 2);        // -o is a folder
  EXPECT_EQ(run_cli("report --list", log), 0);
  EXPECT_NE(read(log).find("feedback.g0.99.rgba8"), std::string::npos);
}

} // namespace
