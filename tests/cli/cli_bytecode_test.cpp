// Token streams wherever a listing goes, the ps_1_x range presets, and binary files where
// text was expected — through the built binary.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_test_util.h"

namespace fs = std::filesystem;
using tierlift::test::listing;
using tierlift::test::run_cli;

namespace {

fs::path scratch(const std::string& name) {
  auto dir = fs::temp_directory_path() / ("tierlift_cli_bc_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

fs::path write(const std::string& name, const std::string& bytes) {
  auto p = scratch(name);
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

std::string le_bytes(const std::vector<uint32_t>& t) {
  std::string out;
  for (uint32_t v : t)
    for (int s = 0; s < 32; s += 8) out += static_cast<char>((v >> s) & 0xFF);
  return out;
}

// With --json the device error is a diagnostic on standard output.
bool no_vulkan(const tierlift::test::CliResult& r) {
  return r.exit_code == 2 && (r.err.find("mesa-vulkan-drivers") != std::string::npos ||
                              r.out.find("mesa-vulkan-drivers") != std::string::npos);
}

// Listing 4 assembled into the token stream `pso`; the assembler's exit status.
int assemble_listing4(const fs::path& pso) {
  return run_cli("assemble " + listing("listing4_blur4_weighted_sum.psh") + " -o " + pso.string())
      .exit_code;
}

} // namespace

TEST(CliBytecode, CheckFmtAndSpirvTakeTokenStreams) {
  auto pso = scratch("l4.pso");
  ASSERT_EQ(assemble_listing4(pso), 0);
  auto check = run_cli("check " + pso.string());
  EXPECT_EQ(check.exit_code, 0) << check.err;
  EXPECT_NE(check.out.find("ok (ps_1_3"), std::string::npos) << check.out;
  auto json = run_cli("check --json " + pso.string());
  EXPECT_NE(json.out.find("\"D3D9 token stream\""), std::string::npos) << json.out;
  auto fmt_bin = run_cli("fmt " + pso.string());
  auto fmt_txt = run_cli("fmt " + listing("listing4_blur4_weighted_sum.psh"));
  EXPECT_EQ(fmt_bin.exit_code, 0) << fmt_bin.err;
  // fmt keeps the text's comments; a token stream has none. Without them the two agree.
  std::string uncommented;
  std::istringstream lines(fmt_txt.out);
  for (std::string line; std::getline(lines, line);) {
    if (auto c = line.find("//"); c != std::string::npos) {
      line.erase(c);
      while (!line.empty() && line.back() == ' ') line.pop_back();
      if (line.empty()) continue; // a line that held only a comment
    }
    uncommented += line + "\n";
  }
  EXPECT_EQ(fmt_bin.out, uncommented);
  auto spirv = run_cli("spirv " + pso.string());
  EXPECT_EQ(spirv.exit_code, 0) << spirv.err;
}

TEST(CliBytecode, BinaryWhereTextWasExpectedIsOneLine) {
  auto png = write("picture.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x01", 20));
  for (const char* cmd : {"check ", "fmt ", "spirv "}) {
    auto r = run_cli(cmd + png.string());
    EXPECT_EQ(r.exit_code, 1) << cmd << r.err;
    EXPECT_NE(r.err.find("PNG image"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("glow --image"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('^'), std::string::npos) << r.err; // no caret line
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

// `run --ps x.pso` and `--ps x.psh`: bit-identical images, on each device.
TEST(CliBytecode, RunDrawsTheSameImageFromTokensAndText) {
  auto pso = scratch("l4run.pso");
  ASSERT_EQ(assemble_listing4(pso), 0);
  std::string common = " --size 32x32 --format rgba32f --filter linear --address clamp";
  for (int k = 0; k < 4; ++k) {
    common += " --const ps:c" + std::to_string(k) + "=0.25,0.25,0.25,0.25";
    common += " --texture s" + std::to_string(k) + "=builtin:noise:32x32";
    common += " --input t" + std::to_string(k) + "=0." + std::to_string(k + 2) + ",0.5,0,1";
  }
  for (const char* backend : {"cpu", "vulkan"}) {
    auto a = scratch(std::string("from_text_") + backend + ".pfm");
    auto b = scratch(std::string("from_tokens_") + backend + ".pfm");
    auto ra = run_cli("run --ps " + listing("listing4_blur4_weighted_sum.psh") + common +
                      " --backend " + backend + " -o " + a.string());
    if (no_vulkan(ra)) continue;
    ASSERT_EQ(ra.exit_code, 0) << ra.err;
    auto rb = run_cli("run --ps " + pso.string() + common + " --backend " + backend + " -o " +
                      b.string());
    ASSERT_EQ(rb.exit_code, 0) << rb.err;
    auto bytes_a = tierlift::test::read_all(a), bytes_b = tierlift::test::read_all(b);
    EXPECT_GT(bytes_a.size(), 32u * 32u * 12u);
    EXPECT_EQ(bytes_a, bytes_b) << backend;
  }
}

// The hand-built CTAB of tests/bytecode/constant_table_test.cpp: g_mWVP in c4..c7 of
// "mov oC0, c4". `--const g_mWVP=` sets c4..c7; the pixel is c4.
TEST(CliBytecode, ConstantTableNamesInDisasmAndRun) {
  std::vector<uint32_t> t = {0xFFFF0200, 0x0016FFFE, 0x42415443, 28,         80,         0xFFFF0200,
                             1,          28,         0,          72,         64,         0x00040002,
                             0x00000004, 48,         0,          0x00030003, 0x00040004, 0x00000001,
                             0,          0x576D5F67, 0x00005056, 0x325F7370, 0x0000305F, 0x00006C74,
                             0x02000001, 0x800F0800, 0xA0E40004, 0x0000FFFF};
  auto pso = write("ctab.pso", le_bytes(t));
  auto d = run_cli("disasm " + pso.string());
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_NE(d.out.find("c4..c7  g_mWVP  float4x4"), std::string::npos) << d.out;
  // The CTAB itself is kept as "//!comment" lines: assembling the disassembly gives back the
  // stream byte for byte (docs/d3d9-rules.md §11.4).
  EXPECT_NE(d.out.find("//!comment 0x42415443 0x0000001c"), std::string::npos) << d.out;
  auto text = write("ctab.asm", d.out);
  auto back = scratch("ctab_back.pso");
  auto a = run_cli("assemble " + text.string() + " -o " + back.string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  std::ifstream in(back, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  EXPECT_EQ(bytes.str(), le_bytes(t));
  auto j = run_cli("check --json " + pso.string());
  EXPECT_NE(j.out.find("\"g_mWVP\""), std::string::npos) << j.out;
  auto r = run_cli("run --ps " + pso.string() +
                   " --size 2x2 --format rgba32f --probe 1,1 --json --const "
                   "g_mWVP=0.25,0.5,0.75,1,0,0,0,0,0,0,0,0,0,0,0,0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto out = nlohmann::json::parse(r.out);
  EXPECT_EQ(out["result"]["probes"][0]["rgba"], nlohmann::json({0.25, 0.5, 0.75, 1.0})) << r.out;
  auto bad = run_cli("run --ps " + pso.string() + " --size 2x2 --const g_nope=1,2,3,4");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("g_nope"), std::string::npos) << bad.err;
}

// ps_1_1: r0 = t0 − 0.5 = (0.3, …); r1 = c0 + c0 = (2, 0, 0, 0) — or (1, 0, 0, 0) where
// registers clamp to ±1; dp3 gives 0.6 or 0.3, and cnd compares it against 0.5: white
// (c1) with the D3D9 range, black (c2) with geforce3's. (The shape of Wine's cnd_test.)
TEST(CliBytecode, Ps1xPresetsDecideTheCnd) {
  auto psh = write("cnd.psh", "ps_1_1\ndef c0, 1, 0, 0, 0\ndef c1, 1, 1, 1, 1\n"
                              "def c2, 0, 0, 0, 1\ndef c3, 0.5, 0.5, 0.5, 0\ntexcoord t0\n"
                              "mov r0, t0\nsub r0, r0, c3\nadd r1, c0, c0\ndp3 r1, r0, r1\n"
                              "mov r0.a, r1.b\ncnd r0, r0.a, c1, c2\n");
  std::string args = "run --ps " + psh.string() +
                     " --size 1x1 --format rgba32f --probe 0,0 --json --input t0=0.8,0,0,1";
  struct Case {
    std::string flag;
    double expect;
    std::string label;
  } cases[] = {{"", 1.0, "d3d9"},
               {" --ps1x-max geforce3", 0.0, "geforce3"},
               {" --ps1x-max radeon8500", 1.0, "radeon8500"},
               {" --ps1x-max 1", 0.0, "geforce3"},
               {" --ps1x-max max", 1.0, "d3d9"}};
  for (const char* backend : {"cpu", "vulkan"})
    for (const Case& c : cases) {
      auto r = run_cli(args + c.flag + " --backend " + backend);
      if (no_vulkan(r)) break;
      ASSERT_EQ(r.exit_code, 0) << c.flag << r.err;
      auto j = nlohmann::json::parse(r.out);
      EXPECT_EQ(j["result"]["probes"][0]["rgba"][0], c.expect) << backend << c.flag;
      EXPECT_EQ(j["result"]["ps1x_max"]["preset"], c.label) << backend << c.flag;
    }
  auto bad = run_cli(args + " --ps1x-max 0.5");
  EXPECT_EQ(bad.exit_code, 2);
  // --json: the error is a diagnostic on standard output.
  EXPECT_NE(bad.out.find("radeon8500"), std::string::npos) << bad.out;
}

TEST(CliBytecode, StrictFlag) {
  auto psh = write("texcrd.psh", "ps_1_4\ntexcrd r0, t0\nmov r0.a, c0.a\n");
  auto lenient = run_cli("check " + psh.string());
  EXPECT_EQ(lenient.exit_code, 0) << lenient.err;
  EXPECT_NE(lenient.err.find("warning:"), std::string::npos) << lenient.err;
  EXPECT_EQ(run_cli("check --strict " + psh.string()).exit_code, 1);
}
