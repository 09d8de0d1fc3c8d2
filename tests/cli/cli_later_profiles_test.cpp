// Shader models 2.x and 3.0 through the command line: check, fmt, assemble, disasm, spirv
// and run take them; what no profile allows (a relative temp destination) is refused with a
// positioned message and exit 1; --profile takes fxc's ps_2_a / ps_2_b presets, the second
// without gradient instructions.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "temp_dir.h"

using tierlift::test::read_all;
using tierlift::test::run_cli;

namespace {

struct Scratch : tierlift::test::TempDir {
  Scratch() : TempDir("later") {}
};

constexpr const char* kPs30 = "ps_3_0\n"
                              "dcl_texcoord0 v0.xy\n"
                              "dcl_2d s0\n"
                              "texld r0, v0, s0\n"
                              "setp_gt p0, r0, c0\n"
                              "(p0) mul r0, r0, c1\n"
                              "mov oC0, r0\n";

// With --json the device error is a diagnostic on standard output.
bool no_vulkan(const tierlift::test::CliResult& r) {
  return r.exit_code == 2 && (r.err.find("mesa-vulkan-drivers") != std::string::npos ||
                              r.out.find("mesa-vulkan-drivers") != std::string::npos);
}

constexpr const char* kVs30 = "vs_3_0\n"
                              "dcl_position v0\n"
                              "dcl_position o0\n"
                              "mov o0, v0\n";

} // namespace

TEST(CliLaterProfiles, CheckFmtAssembleDisasm) {
  Scratch s;
  const std::string ps = s.file("a.psh", kPs30);
  auto check = run_cli("check " + ps);
  EXPECT_EQ(check.exit_code, 0) << check.err;
  auto fmt = run_cli("fmt " + ps + " -o -");
  ASSERT_EQ(fmt.exit_code, 0) << fmt.err;
  EXPECT_NE(fmt.out.find("(p0) mul r0, r0, c1\n"), std::string::npos) << fmt.out;
  EXPECT_NE(fmt.out.find("dcl_texcoord v0.xy\n"), std::string::npos) << fmt.out;
  ASSERT_EQ(run_cli("assemble " + ps + " -o " + s.file("a.bin")).exit_code, 0);
  // ps_3_0 version token 0xFFFF0300, little-endian.
  EXPECT_EQ(read_all(s.file("a.bin")).substr(0, 4), std::string("\x00\x03\xFF\xFF", 4));
  auto dis = run_cli("disasm " + s.file("a.bin") + " -o -");
  ASSERT_EQ(dis.exit_code, 0) << dis.err;
  EXPECT_EQ(dis.out, fmt.out);
  EXPECT_EQ(run_cli("check " + s.file("v.vsh", kVs30)).exit_code, 0);
}

TEST(CliLaterProfiles, SpirvAndRunTakeThemAndRefuseARelativeTempWithAPosition) {
  Scratch s;
  const std::string ps = s.file("a.psh", kPs30);
  auto spirv = run_cli("spirv " + ps + " -o " + s.file("a.spv"));
  EXPECT_EQ(spirv.exit_code, 0) << spirv.err;
  auto run = run_cli("run --ps " + ps + " --const ps:c0=0.5,0.5,0.5,0.5 --const ps:c1=2,2,2,2" +
                     " --backend cpu -o " + s.file("out.png"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(std::filesystem::exists(s.file("out.png")));
  EXPECT_EQ(run_cli("spirv " + s.file("v.vsh", kVs30) + " -o " + s.file("v.spv")).exit_code, 0);
  // An input read relatively runs, and so does an output written relatively (NUMERICS.md
  // F13).
  const std::string rel =
      s.file("g.psh", "ps_3_0\ndcl_texcoord0 v0\ndcl_texcoord1 v1\ndefi i0, 2, 0, 1, 0\n"
                      "mov r0, c0\nloop aL, i0\nadd r0, r0, v0[aL]\nendloop\nmov oC0, r0\n");
  auto g =
      run_cli("run --ps " + rel + " --const ps:c0=0,0,0,0 --backend cpu -o " + s.file("g.png"));
  EXPECT_EQ(g.exit_code, 0) << g.err;
  EXPECT_TRUE(std::filesystem::exists(s.file("g.png")));
  const std::string out_rel =
      s.file("h.vsh", "vs_3_0\ndcl_position v0\ndcl_position o0\ndcl_texcoord0 o1\n"
                      "defi i0, 1, 1, 1, 0\nmov o0, v0\nloop aL, i0\nmov o[aL], v0\nendloop\n");
  auto h = run_cli("spirv " + out_rel + " -o " + s.file("h.spv"));
  EXPECT_EQ(h.exit_code, 0) << h.err;
  EXPECT_TRUE(std::filesystem::exists(s.file("h.spv")));
  // Other relative destinations are no profile's: the validator refuses r[aL] at the operand.
  const std::string r_rel = s.file("r.vsh", "vs_3_0\ndcl_position v0\ndcl_position o0\n"
                                            "defi i0, 1, 1, 1, 0\nmov o0, v0\nloop aL, i0\n"
                                            "mov r[aL], v0\nendloop\n");
  auto r = run_cli("spirv " + r_rel + " -o " + s.file("r.spv"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("r.vsh:7:5: error:"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(s.file("r.spv")));
}

TEST(CliLaterProfiles, ProfilePresetsOfFxc) {
  Scratch s;
  const std::string ps = s.file("b.psh", "ps_2_x\ndcl t0\ndsx r0, t0\nmov oC0, r0\n");
  EXPECT_EQ(run_cli("check " + ps).exit_code, 0);
  EXPECT_EQ(run_cli("check --profile ps_2_a " + ps).exit_code, 0);
  auto b = run_cli("check --profile ps_2_b " + ps);
  EXPECT_EQ(b.exit_code, 1);
  EXPECT_NE(b.err.find("b.psh:3:1: error: dsx is a gradient instruction"), std::string::npos)
      << b.err;
  EXPECT_EQ(run_cli("check --profile ps_2_c " + ps).exit_code, 2);
}

// --front-face: the full-screen quad is wound clockwise, so vFace is +1 by default (Direct3D
// 9's front face) and −1 with --front-face ccw, on both devices; anything else is a usage
// error.
// A ps_3_0 that writes no oC# (a validator warning) leaves the colour undefined in D3D9. Both
// devices draw (0, 0, 0, 0), the value every register starts at: the SPIR-V stores oC0 from
// its register all the same (lavapipe drew what its registers held, 0.549 and -1.07e-4 at one
// pixel; generated ps_3_0 case 00147 of seed 2 was reduced to such a program).
TEST(CliLaterProfiles, NoColourWrittenDrawsZeroOnBothDevices) {
  Scratch s;
  for (const char* body : {"", "def c0, 1, 2, 3, 4\nmov r0, c0\n"}) {
    const std::string ps = s.file("n.psh", std::string("ps_3_0\n") + body);
    for (const char* backend : {"cpu", "vulkan"}) {
      auto r = run_cli("run --ps " + ps + " --size 4x4 --format rgba32f --probe 1,1 --probe 3,2" +
                       " --json --backend " + backend);
      if (no_vulkan(r)) break;
      ASSERT_EQ(r.exit_code, 0) << backend << r.err;
      auto j = nlohmann::json::parse(r.out);
      for (int p = 0; p < 2; ++p)
        for (int c = 0; c < 4; ++c)
          EXPECT_EQ(j["result"]["probes"][p]["rgba"][c], 0.0) << backend << " " << body;
    }
  }
}

TEST(CliLaterProfiles, FrontFaceFlagDecidesVface) {
  Scratch s;
  const std::string ps = s.file("f.psh", "ps_3_0\ndcl vFace\nmov oC0, vFace\n");
  for (const char* backend : {"cpu", "vulkan"})
    for (const auto& [flag, want] : {std::pair{"", 1.0}, std::pair{" --front-face cw", 1.0},
                                     std::pair{" --front-face ccw", -1.0}}) {
      auto r = run_cli("run --ps " + ps + " --size 2x2 --format rgba32f --probe 1,1 --json" + flag +
                       " --backend " + backend);
      if (no_vulkan(r)) break;
      ASSERT_EQ(r.exit_code, 0) << backend << flag << r.err;
      auto j = nlohmann::json::parse(r.out);
      EXPECT_EQ(j["result"]["probes"][0]["rgba"][0], want) << backend << flag;
    }
  auto bad = run_cli("run --ps " + ps + " --size 2x2 --front-face up");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--front-face 'up': expected cw or ccw"), std::string::npos) << bad.err;
}
