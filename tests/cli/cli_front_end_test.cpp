// End-to-end tests of the front-end subcommands through the real binary.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include "cli_test_util.h"
#include "skip_policy.h"

using tierlift::test::listing;
using tierlift::test::run_cli;
namespace fs = std::filesystem;

namespace {

fs::path temp_file(const std::string& name, const std::string& text) {
  auto dir = fs::temp_directory_path() / ("tierlift_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  auto p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// fmt's text minus its comment lines, trailing comments and blank lines.
std::string without_comments(const std::string& text) {
  std::string out;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    std::string line = text.substr(start, end - start);
    start = end + 1;
    if (size_t c = line.find("  //"); c != std::string::npos) line.resize(c);
    if (line.empty() || line.starts_with("//")) continue;
    out += line + "\n";
  }
  return out;
}

const char* kAllArticleListings =
    "listing1_blur8_coords.vsh listing2_blur8_weighted_sum.psh listing3_blur4_coords.vsh "
    "listing4_blur4_weighted_sum.psh";

} // namespace

TEST(CliCheck, ArticleListingsAreValid) {
  std::string args = "check";
  for (const char* n : {"listing1_blur8_coords.vsh", "listing2_blur8_weighted_sum.psh",
                        "listing3_blur4_coords.vsh", "listing4_blur4_weighted_sum.psh"})
    args += " " + listing(n);
  auto r = run_cli(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("listing2_blur8_weighted_sum.psh: ok (ps_2_0"), std::string::npos) << r.out;
  (void)kAllArticleListings;
}

TEST(CliCheck, InvalidListingExitsOneWithCaret) {
  // Line 3, column 1: the 9th arithmetic instruction of a ps_1_3 listing breaks the limit.
  std::string text = "ps.1.3\ntex t0\n";
  for (int i = 0; i < 9; ++i) text += "add r0, t0, c0\n";
  auto p = temp_file("too_long.psh", text);
  auto r = run_cli("check " + p.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("too_long.psh:11:1: error:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("8 arithmetic slots"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\n    ^"), std::string::npos) << r.err;
}

TEST(CliCheck, UnknownMnemonicHasExactPosition) {
  auto p = temp_file("bad_mnemonic.vsh", "vs_1_1\ndcl_position v0\n  frob r0, v0\n");
  auto r = run_cli("check " + p.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad_mnemonic.vsh:3:3: error:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frob"), std::string::npos) << r.err;
}

TEST(CliCheck, MissingFileIsAnIoError) {
  auto r = run_cli("check /nonexistent/dir/x.vsh");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cannot read"), std::string::npos) << r.err;
}

TEST(CliCheck, ReadsStandardInput) {
  auto r = run_cli("check -", "vs.1.1\ndcl_position v0\nmov oPos, v0\n");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  auto bad = run_cli("check -", "vs.1.1\nmov oPos, r0\n");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("<stdin>:2:"), std::string::npos) << bad.err;
}

TEST(CliCheck, JsonDiagnostics) {
  auto r = run_cli("check --json -", "vs.1.1\nmov oPos, r0\n");
  EXPECT_EQ(r.exit_code, 1);
  auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j["command"], "check");
  EXPECT_EQ(j["exit_code"], 1);
  ASSERT_EQ(j["result"]["files"].size(), 1u);
  EXPECT_FALSE(j["result"]["files"][0]["valid"].get<bool>());
  ASSERT_FALSE(j["diagnostics"].empty());
  EXPECT_EQ(j["diagnostics"][0]["file"].get<std::string>(), "<stdin>");
  EXPECT_EQ(j["diagnostics"][0]["line"].get<int>(), 2);
  EXPECT_EQ(j["diagnostics"][0]["severity"].get<std::string>(), "error");
}

TEST(CliCheck, ProfileOverride) {
  // Listing 4 (ps.1.3) also fits ps_1_1; a pixel listing cannot be checked as vs_1_1.
  auto ok = run_cli("check --profile ps_1_1 " + listing("listing4_blur4_weighted_sum.psh"));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  auto wrong = run_cli("check --profile vs_1_1 " + listing("listing4_blur4_weighted_sum.psh"));
  EXPECT_EQ(wrong.exit_code, 1);
  auto unknown = run_cli("check --profile ps_9_9 " + listing("listing4_blur4_weighted_sum.psh"));
  EXPECT_EQ(unknown.exit_code, 2);
  // dp4 does not exist in ps_1_1.
  auto p = temp_file("dp4.psh", "ps.1.3\ntex t0\ndp4 r0, t0, c0\n");
  EXPECT_EQ(run_cli("check " + p.string()).exit_code, 0);
  EXPECT_EQ(run_cli("check --profile ps_1_1 " + p.string()).exit_code, 1);
}

TEST(CliFmt, CanonicalTextReparsesToTheSameText) {
  auto first = run_cli("fmt " + listing("listing2_blur8_weighted_sum.psh"));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(first.out.rfind("ps_2_0\n", 0), 0u) << first.out;
  auto second = run_cli("fmt -", first.out);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(first.out, second.out);
}

TEST(CliFmt, KeepsCommentsAndParagraphs) {
  const std::string in =
      "// header\n\nps.2.0   ; version comment\ndef c0, 1.0, 0, 0, 1 // red\n\n\n"
      "/* block\n   comment */\nmov oC0, c0\n; trailing\n\n";
  // Written by hand: canonical statements, comments where they were, one blank line per
  // run of blank lines, none at the end.
  const std::string want = "// header\n\nps_2_0  ; version comment\ndef c0, 1, 0, 0, 1  // red\n\n"
                           "/* block\ncomment */\nmov oC0, c0\n; trailing\n";
  auto r = run_cli("fmt -", in);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, want);
  auto again = run_cli("fmt -", r.out);
  EXPECT_EQ(again.out, want);
}

TEST(CliAssemble, RoundTripThroughDisasm) {
  auto dir = fs::temp_directory_path() / ("tierlift_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  auto bin = dir / "l2.bin";
  fs::remove(bin);
  auto a =
      run_cli("assemble " + listing("listing2_blur8_weighted_sum.psh") + " -o " + bin.string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  // ps_2_0 version token, little-endian, first.
  std::string bytes = tierlift::test::read_all(bin);
  ASSERT_GE(bytes.size(), 8u);
  EXPECT_EQ(static_cast<unsigned char>(bytes[0]), 0x00);
  EXPECT_EQ(static_cast<unsigned char>(bytes[1]), 0x02);
  EXPECT_EQ(static_cast<unsigned char>(bytes[2]), 0xFF);
  EXPECT_EQ(static_cast<unsigned char>(bytes[3]), 0xFF);
  auto d = run_cli("disasm " + bin.string());
  ASSERT_EQ(d.exit_code, 0) << d.err;
  // A token stream has no comments: it reads back as fmt's text without them.
  auto f = run_cli("fmt " + listing("listing2_blur8_weighted_sum.psh"));
  f.out = without_comments(f.out);
  EXPECT_EQ(d.out, f.out);
  // The C-array form reads back the same.
  auto carr = dir / "l2.h";
  ASSERT_EQ(run_cli("assemble --c-array " + listing("listing2_blur8_weighted_sum.psh") + " -o " +
                    carr.string())
                .exit_code,
            0);
  EXPECT_EQ(run_cli("disasm " + carr.string()).out, f.out);
}

TEST(CliAssemble, InvalidInputWritesNothing) {
  auto dir = fs::temp_directory_path() / ("tierlift_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  auto out = dir / "never.bin";
  fs::remove(out);
  auto p = temp_file("nooutput.vsh", "vs.1.1\nmov r0, v0\n"); // oPos never written
  auto r = run_cli("assemble " + p.string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(fs::exists(out));
  // fxc /Vd: the same fragment assembles when validation is skipped.
  auto s = run_cli("assemble --skip-validation " + p.string() + " -o " + out.string());
  EXPECT_EQ(s.exit_code, 0) << s.err;
  EXPECT_TRUE(fs::exists(out));
  // Unwritable output: I/O error, exit 2.
  auto w = run_cli("assemble " + listing("listing3_blur4_coords.vsh") + " -o /nonexistent/x.bin");
  EXPECT_EQ(w.exit_code, 2);
}

TEST(CliDisasm, GarbageIsAnErrorNotACrash) {
  auto p = temp_file("garbage.bin", std::string("\x01\x02\x03\x04\x05\x06\x07\x08", 8));
  auto r = run_cli("disasm " + p.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("error"), std::string::npos);
}

TEST(CliMisc, VersionHelpAndUsage) {
  auto v = run_cli("--version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_NE(v.out.find("tierlift "), std::string::npos);
  auto h = run_cli("--help");
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_NE(h.out.find("Examples:"), std::string::npos);
  EXPECT_EQ(run_cli("check").exit_code, 2);
  EXPECT_EQ(run_cli("frobnicate").exit_code, 2);
  EXPECT_EQ(run_cli("").exit_code, 2);
}

TEST(CliListings, BuiltInListingsCheckFromAnyDirectory) {
  auto r = run_cli("listings -q");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("gpugems21/listing1_blur8_coords.vsh: ok (vs_2_0"), std::string::npos);
  EXPECT_NE(r.out.find("gpugems21/listing4_blur4_weighted_sum.psh: ok (ps_1_3"), std::string::npos);
}

TEST(CliSpirv, CompilesValidatesAndExplainsPruning) {
  auto ok = run_cli("spirv " + listing("listing2_blur8_weighted_sum.psh"));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("spirv-val passed"), std::string::npos) << ok.out;
  // Listing 1 writes oT0..oT7, Listing 4 reads t0..t3: oT4..oT7 are left out.
  auto pruned = run_cli("spirv " + listing("listing1_blur8_coords.vsh") + " --pair " +
                        listing("listing4_blur4_weighted_sum.psh") + " --explain");
  EXPECT_EQ(pruned.exit_code, 0) << pruned.err;
  for (const char* reg : {"oT4", "oT5", "oT6", "oT7"})
    EXPECT_NE(pruned.out.find(reg), std::string::npos) << reg << "\n" << pruned.out;
  EXPECT_EQ(pruned.out.find("oT3"), std::string::npos) << pruned.out;
  auto dis = run_cli("spirv --dis " + listing("listing4_blur4_weighted_sum.psh"));
  EXPECT_EQ(dis.exit_code, 0) << dis.err;
  EXPECT_NE(dis.out.find("OpEntryPoint Fragment"), std::string::npos);
  // A listing that fails validation never reaches codegen.
  auto bad = run_cli("spirv -", "vs.1.1\nmov r0, v0\n");
  EXPECT_EQ(bad.exit_code, 1);
}

TEST(CliRun, BothBackendsAgreeOnListings3And4) {
  // A 4-tap box blur of noise: the CPU interpreter and lavapipe must agree (RGBA8: ≤ 1 LSB,
  // ≥ 99.9 % identical). Offsets carry the half texel: (k + 0.5)/64 for k = -2..1.
  std::string args = "run --vs " + listing("listing3_blur4_coords.vsh") + " --ps " +
                     listing("listing4_blur4_weighted_sum.psh") +
                     " --size 64x64 --format rgba8 --attr v3=quad-uv --filter linear"
                     " --address clamp --backend both";
  const char* offsets[] = {"-0.0234375", "-0.0078125", "0.0078125", "0.0234375"};
  for (int k = 0; k < 4; ++k) {
    args += " --const vs:c" + std::to_string(k) + "=" + offsets[k] + ",0,0,0";
    args += " --const ps:c" + std::to_string(k) + "=0.25,0.25,0.25,0.25";
    args += " --texture s" + std::to_string(k) + "=builtin:noise:64x64";
  }
  auto r = run_cli(args);
  if (r.exit_code == 2 && r.err.find("no Vulkan device found") != std::string::npos)
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device: " + r.err);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("within targets"), std::string::npos) << r.out;
}
