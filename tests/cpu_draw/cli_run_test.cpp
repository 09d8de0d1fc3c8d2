// `tierlift run` as a process: exit codes, probes on stdout, atomic output files. Skipped
// when the CLI binary has not been built in this build tree.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

struct Result {
  int code;
  std::string out;
};

Result run_cli(const std::string& args) {
  std::string cmd = std::string(TIERLIFT_CLI_PATH) + " run " + args + " 2>/dev/null";
  Result r{-1, {}};
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

class CliRun : public ::testing::Test {
protected:
  void SetUp() override {
    // The CLI is built with the tests; its absence is a broken build, never a skip.
    ASSERT_TRUE(fs::exists(TIERLIFT_CLI_PATH)) << "tierlift CLI not built: " << TIERLIFT_CLI_PATH;
    dir_ = fs::temp_directory_path() / ("tierlift_cli_run_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
  }
  size_t files_in_dir() const {
    size_t n = 0;
    for (auto& e : fs::directory_iterator(dir_)) n += e.is_regular_file();
    return n;
  }
  fs::path dir_;
};

const std::string kL = std::string(TIERLIFT_SOURCE_DIR) + "/listings/gpugems21/";

// Listings 3+4 with the half-texel offsets over a 16-wide ramp: pixel 0 = 0.125 (see
// run_job_test.cpp), pixel 5 = (5.5+6.5+7.5+8.5)/64 = 0.4375.
TEST_F(CliRun, BlurProbesAndOutput) {
  std::string args = "--vs " + kL + "listing3_blur4_coords.vsh --ps " + kL +
                     "listing4_blur4_weighted_sum.psh --size 16x16 --format rgba32f "
                     "--attr v3=quad-uv --filter linear --address clamp --threads 2";
  for (int k = 0; k < 4; ++k) {
    args +=
        " --const vs:c" + std::to_string(k) + "=" + std::to_string((k + 0.5) / 16) + ",0.03125,0,0";
    args += " --const ps:c" + std::to_string(k) + "=0.25,0.25,0.25,0.25";
    args += " --texture s" + std::to_string(k) + "=builtin:ramp:16x16";
  }
  fs::path out = dir_ / "blur.pfm";
  Result r = run_cli(args + " --probe 0,0 --probe 5,3 -o " + out.string());
  ASSERT_EQ(r.code, 0);
  EXPECT_EQ(r.out, "0,0: 0.125 0.125 0.125 1\n5,3: 0.4375 0.4375 0.4375 1\n");
  EXPECT_TRUE(fs::exists(out));
  EXPECT_EQ(files_in_dir(), 1u); // no temporary left behind
}

TEST_F(CliRun, ExitCodesAndNoOutputOnFailure) {
  fs::path out = dir_ / "never.png";
  // Invalid input (a constant the listing reads is missing): 1, no file.
  EXPECT_EQ(run_cli("--ps " + kL + "listing4_blur4_weighted_sum.psh -o " + out.string()).code, 1);
  // Usage errors: 2.
  EXPECT_EQ(run_cli("--size 16385x16 -o " + out.string()).code, 2);
  EXPECT_EQ(run_cli("--format rgb565").code, 2);
  EXPECT_EQ(run_cli("--const c0=1,2").code, 2);
  EXPECT_EQ(run_cli("--probe 9,9 --size 4x4").code, 2);
  EXPECT_EQ(run_cli("--vs /nonexistent.vsh").code, 2);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(CliRun, JsonSummary) {
  Result r = run_cli("--input v0=1,0,0,1 --size 3x2 --probe 2,1 --json");
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("\"width\": 3"), std::string::npos);
  // One default format for run and glow: rgba32f (docs/command-line.md).
  EXPECT_NE(r.out.find("\"format\": \"rgba32f\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"timing_ms\""), std::string::npos);
}

// --mips, --mip-filter, --max-mip-level and "mips:" levels (docs/command-line.md). texldl at
// (½, ½) with lod 0 reads: the 16×16 checker's level 0 texel (8, 8) = 1; its generated
// level 4 (1×1, the box average of two white and two black 8×8 blocks) = 0.5 under MIPFILTER
// NONE with MAXMIPLEVEL 4; a given level 1 (an 8×8 ramp, texel 4 = 4.5/8) under POINT with
// MAXMIPLEVEL 1, which clamps the lod from below.
TEST_F(CliRun, MipChainsAndMipState) {
  const fs::path ps = dir_ / "lod.psh";
  std::ofstream(ps)
      << "ps_3_0\ndcl_2d s0\ndef c0, 0.5, 0.5, 0, 0\nmov r1, c0\ntexldl r0, r1, s0\nmov oC0, r0\n";
  const std::string base = "--ps " + ps.string() + " --size 2x2 --format rgba32f --probe 0,0 ";
  const std::string checker = " --texture s0=builtin:checker:16x16";
  EXPECT_EQ(run_cli(base + checker).out, "0,0: 1 1 1 1\n");
  EXPECT_EQ(run_cli(base + checker + " --mips auto --max-mip-level 4").out, "0,0: 0.5 0.5 0.5 1\n");
  EXPECT_EQ(run_cli(base + checker + " --mips 3 --max-mip-level 4").out, "0,0: 1 1 1 1\n");
  const std::string given = " --texture s0=mips:builtin:checker:16x16,builtin:ramp:8x8";
  EXPECT_EQ(run_cli(base + given + " --mip-filter point --max-mip-level 1").out,
            "0,0: 0.5625 0.5625 0.5625 1\n");
  // A level of the wrong size is refused; so are bad flag values (usage errors, exit 2).
  EXPECT_NE(run_cli(base + " --texture s0=mips:builtin:checker:16x16,builtin:ramp:4x4").code, 0);
  EXPECT_EQ(run_cli(base + checker + " --mips 0").code, 2);
  EXPECT_EQ(run_cli(base + checker + " --mip-filter cubic").code, 2);
  EXPECT_EQ(run_cli(base + checker + " --max-mip-level 40").code, 2);
}

} // namespace
