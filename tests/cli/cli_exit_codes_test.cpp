// Every command's exit codes (0 ok, 1 invalid input or disagreement, 2 usage or I/O) and
// the output rules: an input is never overwritten, a failed write leaves no file and no
// temporary, -o - is standard output, readers refuse what is over their cap.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "temp_dir.h"

using tierlift::test::listing;
using tierlift::test::read_all;
using tierlift::test::run_cli;
namespace fs = std::filesystem;

namespace {

constexpr const char* kValidPs = "ps_2_0\ndef c0, 0.25, 0.5, 0.75, 1\nmov oC0, c0\n";
constexpr const char* kInvalidPs = "ps_2_0\nmov oC0, r9\n"; // r9 was never written

// A fresh folder per test, removed afterwards.
struct Scratch : tierlift::test::TempDir {
  Scratch() : TempDir("exit") {}
};

// A folder nothing can be created in, even by root (who ignores permission bits).
std::string unwritable_folder(const Scratch& s) {
  if (::geteuid() == 0) return "/proc/self";
  fs::create_directories(s.path() / "ro");
  fs::permissions(s.path() / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  return s.file("ro");
}

} // namespace

TEST(ExitCodes, NoArgumentsIsUsage) {
  EXPECT_EQ(run_cli("").exit_code, 2);
  auto r = run_cli("run");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nothing to draw"), std::string::npos) << r.err;
  for (const char* cmd : {"check", "fmt", "assemble", "disasm", "spirv"})
    EXPECT_EQ(run_cli(cmd).exit_code, 2) << cmd;
  EXPECT_EQ(run_cli("listings --no-such-flag").exit_code, 2);
  auto v = run_cli("-V");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.out.rfind("tierlift ", 0), 0u) << v.out;
}

TEST(ExitCodes, Check) {
  Scratch s;
  EXPECT_EQ(run_cli("check " + s.file("ok.psh", kValidPs)).exit_code, 0);
  EXPECT_EQ(run_cli("check " + s.file("bad.psh", kInvalidPs)).exit_code, 1);
  EXPECT_EQ(run_cli("check " + s.file("missing.psh")).exit_code, 2);
  EXPECT_EQ(run_cli("check " + s.path().string()).exit_code, 2);
}

TEST(ExitCodes, CheckRefusesDevZeroNamingTheCap) {
  auto r = run_cli("check /dev/zero");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/dev/zero: too large for a listing: the cap is 4 MiB"), std::string::npos)
      << r.err;
}

TEST(ExitCodes, ByteOrderMarkIsAccepted) {
  Scratch s;
  auto r = run_cli("check " + s.file("bom.psh", std::string("\xEF\xBB\xBF") + kValidPs));
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(ExitCodes, FmtAndItsOutput) {
  Scratch s;
  const std::string in = s.file("a.psh", kValidPs);
  auto ok = run_cli("fmt " + in + " -o " + s.file("out.psh"));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(ok.out.empty());
  auto dash = run_cli("fmt " + in + " -o -");
  EXPECT_EQ(dash.exit_code, 0);
  EXPECT_EQ(dash.out, read_all(s.file("out.psh")));
  EXPECT_EQ(run_cli("fmt " + s.file("bad.psh", kInvalidPs)).exit_code, 1);
  EXPECT_EQ(run_cli("fmt " + s.file("missing.psh")).exit_code, 2);
  // The output is the input: refused, the file untouched.
  auto same = run_cli("fmt " + in + " -o " + in);
  EXPECT_EQ(same.exit_code, 2);
  EXPECT_NE(same.err.find("refusing to write over"), std::string::npos) << same.err;
  EXPECT_EQ(read_all(in), kValidPs);
}

TEST(ExitCodes, AssembleNeverOverwritesItsInput) {
  Scratch s;
  const std::string in = s.file("x.psh", kValidPs);
  auto r = run_cli("assemble " + in + " -o " + in);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_all(in), kValidPs);
  // Another name for the same file (a hard link) is the same file.
  fs::create_hard_link(in, s.file("alias.psh"));
  EXPECT_EQ(run_cli("assemble " + in + " -o " + s.file("alias.psh")).exit_code, 2);
  EXPECT_EQ(read_all(in), kValidPs);
  EXPECT_EQ(s.names(), (std::vector<std::string>{"alias.psh", "x.psh"}));
}

TEST(ExitCodes, AssembleToStandardOutput) {
  Scratch s;
  auto r = run_cli("assemble " + s.file("a.psh", kValidPs) + " -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The version token of ps_2_0, little-endian: 0xFFFF0200.
  ASSERT_GE(r.out.size(), 4u);
  EXPECT_EQ(r.out.substr(0, 4), std::string("\x00\x02\xFF\xFF", 4));
  EXPECT_EQ(s.names(), std::vector<std::string>{"a.psh"}) << "no file named '-'";
  EXPECT_EQ(run_cli("assemble " + s.file("a.psh") + " -o - --json").exit_code, 2);
}

TEST(ExitCodes, AssembleIntoAnUnwritableOrMissingFolderLeavesNothing) {
  Scratch s;
  const std::string in = s.file("a.psh", kValidPs);
  const std::string ro = unwritable_folder(s);
  auto r = run_cli("assemble " + in + " -o " + ro + "/out.bin");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(fs::exists(ro + "/out.bin"));
  if (::geteuid() != 0) {
    EXPECT_TRUE(fs::is_empty(ro)) << "a temporary file was left";
  }
  auto m = run_cli("assemble " + in + " -o " + s.file("no/such/out.bin"));
  EXPECT_EQ(m.exit_code, 2);
  EXPECT_FALSE(fs::exists(s.file("no")));
}

TEST(ExitCodes, AssembleIncludeDirTakesOneValue) {
  Scratch s;
  fs::create_directories(s.path() / "inc");
  std::ofstream(s.path() / "inc" / "colour.h") << "def c0, 1, 0, 0, 1\n";
  const std::string in = s.file("a.psh", "ps_2_0\n#include \"colour.h\"\nmov oC0, c0\n");
  auto r = run_cli("assemble -I " + s.file("inc") + " " + in + " -o " + s.file("a.bin"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(s.file("a.bin")));
  auto d = run_cli("check -D FOO -D BAR=2 " + in + " -I " + s.file("inc"));
  EXPECT_EQ(d.exit_code, 0) << d.err;
}

TEST(ExitCodes, Disasm) {
  Scratch s;
  ASSERT_EQ(run_cli("assemble " + s.file("a.psh", kValidPs) + " -o " + s.file("a.bin")).exit_code,
            0);
  auto ok = run_cli("disasm " + s.file("a.bin") + " -o " + s.file("a.txt"));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(read_all(s.file("a.txt")).rfind("ps_2_0", 0), 0u);
  EXPECT_EQ(run_cli("disasm " + s.file("junk.bin", std::string("\x01\x02\x03\x04", 4))).exit_code,
            1);
  EXPECT_EQ(run_cli("disasm " + s.file("missing.bin")).exit_code, 2);
  const std::string bin = read_all(s.file("a.bin"));
  EXPECT_EQ(run_cli("disasm " + s.file("a.bin") + " -o " + s.file("a.bin")).exit_code, 2);
  EXPECT_EQ(read_all(s.file("a.bin")), bin);
  auto zero = run_cli("disasm /dev/zero");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.err.find("too large for a token file"), std::string::npos) << zero.err;
}

TEST(ExitCodes, Spirv) {
  Scratch s;
  const std::string in = s.file("a.psh", kValidPs);
  EXPECT_EQ(run_cli("spirv " + in).exit_code, 0);
  EXPECT_EQ(run_cli("spirv " + s.file("bad.psh", kInvalidPs)).exit_code, 1);
  EXPECT_EQ(run_cli("spirv " + s.file("missing.psh")).exit_code, 2);
  EXPECT_EQ(run_cli("spirv " + in + " -o " + in).exit_code, 2);
  EXPECT_EQ(read_all(in), kValidPs);
  auto dash = run_cli("spirv " + in + " -o -");
  ASSERT_EQ(dash.exit_code, 0) << dash.err;
  ASSERT_GE(dash.out.size(), 4u);
  EXPECT_EQ(dash.out.substr(0, 4), std::string("\x03\x02\x23\x07", 4)); // SPIR-V magic
}

TEST(ExitCodes, Run) {
  Scratch s;
  const std::string ps = s.file("a.psh", kValidPs);
  auto ok = run_cli("run --ps " + ps + " --size 4x2 --probe 0,0");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(run_cli("run --ps " + s.file("bad.psh", kInvalidPs) + " --size 4x2").exit_code, 1);
  EXPECT_EQ(run_cli("run --ps " + s.file("missing.psh")).exit_code, 2);
  EXPECT_EQ(run_cli("run --ps " + ps + " --texture s0=" + s.file("missing.png")).exit_code, 2);
  EXPECT_EQ(run_cli("run --ps " + ps + " --size 4x2 -o " + ps).exit_code, 2);
  EXPECT_EQ(read_all(ps), kValidPs);
  // --texture inputs are inputs too.
  ASSERT_EQ(run_cli("run --ps " + ps + " --size 4x2 -o " + s.file("t.png")).exit_code, 0);
  const std::string png = read_all(s.file("t.png"));
  EXPECT_EQ(run_cli("run --ps " + ps + " --size 4x2 --texture s0=" + s.file("t.png") + " -o " +
                    s.file("t.png"))
                .exit_code,
            2);
  EXPECT_EQ(read_all(s.file("t.png")), png);
  auto dash = run_cli("run --ps " + ps + " --size 4x2 -o -");
  ASSERT_EQ(dash.exit_code, 0) << dash.err;
  EXPECT_EQ(dash.out, png);
}

TEST(ExitCodes, RunTakesTheFrontEndFlags) {
  Scratch s;
  const std::string ps = s.file("m.psh", "ps_2_0\ndef c0, VALUE, 0, 0, 1\nmov oC0, c0\n");
  auto r = run_cli("run -D VALUE=0.5 --ps " + ps + " --size 1x1 --probe 0,0 --format rgba32f");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("0,0: 0.5 0 0 1"), std::string::npos) << r.out;
  // A fragment that does not validate (r0 read before written) runs with --skip-validation.
  const std::string frag = s.file("f.psh", "ps_2_0\nmov oC0, r0\n");
  EXPECT_EQ(run_cli("run --ps " + frag + " --size 1x1").exit_code, 1);
  EXPECT_EQ(run_cli("run --skip-validation --ps " + frag + " --size 1x1").exit_code, 0);
  EXPECT_EQ(run_cli("run --profile vs_2_0 --ps " + ps + " -D VALUE=1 --size 1x1").exit_code, 1);
}

TEST(ExitCodes, RunConstTakesWhatDefTakes) {
  Scratch s;
  const std::string ps = s.file("c.psh", "ps_2_0\nmov oC0, c0\n");
  // 0x3f000000 is 0.5; 1e-40 is a denormal strtof keeps; -inf and nan by name.
  auto r = run_cli("run --ps " + ps +
                   " --size 1x1 --probe 0,0 --format rgba32f --const ps:c0=0x3f000000,1e-40f,"
                   "-inf,+0.25");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("0,0: 0.5 "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" 0.25\n"), std::string::npos) << r.out;
  EXPECT_EQ(run_cli("run --ps " + ps + " --size 1x1 --const ps:c0=0x7fc00000,0,0,0").exit_code, 0);
  EXPECT_EQ(run_cli("run --ps " + ps + " --size 1x1 --const ps:c0=1e39,0,0,0").exit_code, 2);
  EXPECT_EQ(run_cli("run --ps " + ps + " --size 1x1 --const ps:c0=-0x1,0,0,0").exit_code, 2);
}

TEST(ExitCodes, Glow) {
  Scratch s;
  const std::string scene = s.file(
      "s.json", R"({"image": "builtin:neon", "size": [32, 16], "glow": {"format": "rgba32f"}})");
  auto ok = run_cli("glow --backend cpu -q --scene " + scene);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(
      run_cli("glow --backend cpu -q --scene " + s.file("bad.json", "{\"size\": 3}")).exit_code, 1);
  EXPECT_EQ(run_cli("glow --backend cpu -q --scene " + s.file("missing.json")).exit_code, 2);
  EXPECT_EQ(run_cli("glow --backend cpu -q --image " + s.file("missing.png")).exit_code, 2);
  EXPECT_EQ(run_cli("glow --backend cpu -q --scene " + s.path().string()).exit_code, 2);
  EXPECT_EQ(run_cli("glow --backend cpu -q --scene " + scene + " -o -").exit_code, 2);
  auto zero = run_cli("glow --backend cpu -q --scene /dev/zero");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.err.find("the cap is 1 MiB"), std::string::npos) << zero.err;
}

TEST(ExitCodes, JsonIsOneDocumentOnStandardOutput) {
  Scratch s;
  auto bad = run_cli("check --json " + s.file("bad.psh", kInvalidPs) + " " + s.file("none.psh"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(bad.err.empty()) << bad.err;
  auto j = nlohmann::json::parse(bad.out);
  EXPECT_EQ(j["command"], "check");
  EXPECT_EQ(j["exit_code"], 2);
  EXPECT_EQ(j["ok"], false);
  ASSERT_EQ(j["diagnostics"].size(), 2u) << j.dump(2);
  EXPECT_EQ(j["diagnostics"][0]["line"], 2);
  EXPECT_EQ(j["diagnostics"][1]["rule"], "io");
  EXPECT_EQ(j["result"]["files"].size(), 2u);
  // The same shape from a command that computes something.
  auto run = run_cli("run --json --ps " + s.file("a.psh", kValidPs) + " --size 2x1 --probe 1,0");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto r = nlohmann::json::parse(run.out);
  EXPECT_EQ(r["command"], "run");
  EXPECT_TRUE(r["diagnostics"].empty());
  EXPECT_EQ(r["result"]["probes"][0]["x"], 1);
  auto fmt = run_cli("fmt --json " + s.file("a.psh"));
  ASSERT_EQ(fmt.exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(fmt.out)["result"]["text"].get<std::string>().rfind("ps_2_0", 0),
            0u);
}

// Errors the argument parser itself finds (unknown flag, missing value, bad choice) give
// the same one document under --json: exit 2, the usage error as a diagnostic.
TEST(ExitCodes, JsonParserErrorsAreOneDocument) {
  Scratch s;
  const std::string ps = s.file("a.psh", kValidPs);
  struct Case {
    std::string args, command;
  };
  for (const Case& c : {Case{"check --json --no-such-flag " + ps, "check"},
                        Case{"run --json --ps " + ps + " --size", "run"},
                        Case{"run --json --ps " + ps + " --backend nowhere", "run"},
                        Case{"--json --no-such-flag", "tierlift"}}) {
    auto r = run_cli(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_TRUE(r.err.empty()) << c.args << ": " << r.err;
    nlohmann::json j;
    ASSERT_NO_THROW(j = nlohmann::json::parse(r.out)) << c.args << ": " << r.out;
    EXPECT_EQ(j["command"], c.command) << c.args;
    EXPECT_EQ(j["exit_code"], 2);
    EXPECT_EQ(j["ok"], false);
    ASSERT_EQ(j["diagnostics"].size(), 1u) << j.dump(2);
    EXPECT_EQ(j["diagnostics"][0]["rule"], "usage");
    EXPECT_EQ(j["diagnostics"][0]["severity"], "error");
    EXPECT_EQ(j["diagnostics"][0]["line"], 0);
    EXPECT_FALSE(j["diagnostics"][0]["message"].get<std::string>().empty());
    EXPECT_TRUE(j["result"].is_object());
  }
  // Without --json the parser's text on standard error, nothing on standard output.
  auto text = run_cli("check --no-such-flag " + ps);
  EXPECT_EQ(text.exit_code, 2);
  EXPECT_TRUE(text.out.empty()) << text.out;
  EXPECT_NE(text.err.find("no-such-flag"), std::string::npos) << text.err;
}

// glow takes run's listing flags, for a scene's listing files and the built-in listings.
TEST(ExitCodes, GlowTakesTheListingFlags) {
  Scratch s;
  // extract_sources.psh (rgb × alpha) with its mul spelled as a macro.
  s.file("ex.psh", "ps_2_0\ndcl t0.xy\ndcl_2d s0\ntexld r0, t0, s0\nMULOP r0.rgb, r0, r0.a\n"
                   "mov oC0, r0\n");
  const std::string macro = s.file("m.json", R"({"image": "builtin:neon", "size": [32, 16],
                    "glow": {"listings": {"glow/extract_sources.psh": "ex.psh"}}})");
  EXPECT_EQ(run_cli("glow --backend cpu -q --scene " + macro).exit_code, 1);
  auto defined = run_cli("glow --backend cpu -q --scene " + macro + " -D MULOP=mul");
  EXPECT_EQ(defined.exit_code, 0) << defined.err;
  // 70 movs: past ps_2_0's 64 arithmetic slots; it still draws what extract_sources does.
  std::string big = "ps_2_0\ndcl t0.xy\ndcl_2d s0\ntexld r0, t0, s0\n";
  for (int i = 0; i < 70; ++i) big += "mov r0, r0\n";
  s.file("big.psh", big + "mul r0.rgb, r0, r0.a\nmov oC0, r0\n");
  const std::string over = s.file("b.json", R"({"image": "builtin:neon", "size": [32, 16],
                    "glow": {"listings": {"glow/extract_sources.psh": "big.psh"}}})");
  auto refused = run_cli("glow --backend cpu -q --scene " + over);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("[slot-limit]"), std::string::npos) << refused.err;
  auto skipped = run_cli("glow --backend cpu -q --skip-validation --scene " + over);
  EXPECT_EQ(skipped.exit_code, 0) << skipped.err;
  // --profile ps_1_1 on the built-in dx9 listings: ps_1_1 has no dcl; line 4 of
  // glow/extract_sources.psh is its first dcl, column 1.
  const std::string plain = s.file("p.json", R"({"image": "builtin:neon", "size": [32, 16]})");
  EXPECT_EQ(run_cli("glow --backend cpu -q --scene " + plain).exit_code, 0);
  auto strict = run_cli("glow --backend cpu -q --profile ps_1_1 --scene " + plain);
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_NE(strict.err.find("glow/extract_sources.psh:4:1: error:"), std::string::npos)
      << strict.err;
  EXPECT_NE(strict.err.find("[not-in-profile]"), std::string::npos) << strict.err;
  EXPECT_EQ(run_cli("glow --backend cpu -q --profile ps_9_9 --scene " + plain).exit_code, 2);
}
