// `tierlift run --trace X,Y` as a user runs it: the table on standard output, the JSON
// result's "trace" (rows of {line, text, dest, interpreter, vulkan}), one column with
// --backend cpu, both with --backend both, and usage errors for a pixel it cannot follow.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "skip_policy.h"
#include "temp_dir.h"

namespace {

using tierlift::test::run_cli;

// t0 = (i/8, j/4, 0, 1) at pixel (i, j) with D3D9 centres; at (3, 2): (0.375, 0.5, 0, 1).
const char* kVs = "vs_2_0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\nmov oT0, v3\n";
const char* kPs = "ps_2_0\n"
                  "def c0, 2, 4, 0.5, 1\n"
                  "dcl t0\n"
                  "mul r0, t0, c0\n" // line 4: (0.75, 2, 0, 1)
                  "add r1, r0, c1\n" // line 5: + c1 (--const)
                  "mov oC0, r1\n";   // line 6

std::string args(const tierlift::test::TempDir& d, const std::string& more) {
  return "run --vs " + d.file("uv.vsh", kVs) + " --ps " + d.file("math.psh", kPs) +
         " --attr v3=quad-uv --size 8x4 --const ps:c1=0.5,0.25,1,-1 " + more;
}

bool no_vulkan(const tierlift::test::CliResult& r) {
  return r.exit_code == 2 && r.err.find("no Vulkan device found") != std::string::npos;
}

TEST(CliTrace, CpuTableNamesEachInstructionWithItsValue) {
  tierlift::test::TempDir d("cli_trace");
  auto r = run_cli(args(d, "--trace 3,2"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("trace of pixel 3,2 (interpreter):"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("    4  mul r0, t0, c0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("r0 = (0.75, 2, 0, 1)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("r1 = (1.25, 2.25, 1, 0)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("oC0 = (1.25, 2.25, 1, 0)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("first difference"), std::string::npos) << r.out;
}

TEST(CliTrace, JsonCarriesTheRows) {
  tierlift::test::TempDir d("cli_trace");
  auto r = run_cli(args(d, "--trace 3,2 --json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const nlohmann::json& t = j["result"]["trace"];
  EXPECT_EQ(t["x"], 3);
  EXPECT_EQ(t["y"], 2);
  ASSERT_EQ(t["rows"].size(), 3u);
  const nlohmann::json& mul = t["rows"][0];
  EXPECT_EQ(mul["line"], 4);
  EXPECT_EQ(mul["text"], "mul r0, t0, c0");
  EXPECT_EQ(mul["dest"], "r0");
  EXPECT_EQ(mul["interpreter"], nlohmann::json({0.75, 2.0, 0.0, 1.0}));
  EXPECT_EQ(mul["interpreter_bits"][0], "0x3f400000");
  EXPECT_TRUE(mul["vulkan"].is_null()); // --backend cpu: the interpreter's column only
  EXPECT_EQ(t["rows"][1]["interpreter"], nlohmann::json({1.25, 2.25, 1.0, 0.0}));
  EXPECT_TRUE(t["first_difference"].is_null());
}

TEST(CliTrace, BothBackendsSideBySide) {
  tierlift::test::TempDir d("cli_trace");
  auto r = run_cli(args(d, "--trace 3,2 --backend both --json"));
  if (no_vulkan(r))
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device: " + r.err);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json t = nlohmann::json::parse(r.out)["result"]["trace"];
  ASSERT_EQ(t["rows"].size(), 3u);
  for (const auto& row : t["rows"]) EXPECT_EQ(row["vulkan"], row["interpreter"]) << row;
  EXPECT_EQ(t["rows"][2]["vulkan"], nlohmann::json({1.25, 2.25, 1.0, 0.0}));
  EXPECT_TRUE(t["first_difference"].is_null());
  auto text = run_cli(args(d, "--trace 3,2 --backend both"));
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("(interpreter | vulkan)"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("no difference: the 3 recorded instructions agree bit for bit"),
            std::string::npos)
      << text.out;
}

TEST(CliTrace, APixelItCannotFollowIsAUsageError) {
  tierlift::test::TempDir d("cli_trace");
  for (const char* bad : {"8,0", "0,4", "3", "a,b"}) {
    auto r = run_cli(args(d, std::string("--trace ") + bad));
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("--trace"), std::string::npos) << r.err;
  }
  auto no_ps = run_cli("run --input v0=1,0,0,1 --trace 0,0");
  EXPECT_EQ(no_ps.exit_code, 2);
  EXPECT_NE(no_ps.err.find("give --ps"), std::string::npos) << no_ps.err;
}

} // namespace
