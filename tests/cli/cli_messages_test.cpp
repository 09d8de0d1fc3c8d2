// Exit codes and messages that used to mislead (issue 32, item 11): usage errors exit 2,
// values out of range are refused, messages say what a file is, scene errors are positioned
// under --json, CR-only files have lines, and the number of errors shown is capped.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "temp_dir.h"

using tierlift::test::run_cli;

namespace {

struct Scratch : tierlift::test::TempDir {
  Scratch() : TempDir("messages") {}
};

constexpr const char* kPs = "ps_2_0\ndef c0, 0.25, 0.5, 0.75, 1\nmov oC0, c0\n";

size_t count(const std::string& text, const std::string& word) {
  size_t n = 0;
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

TEST(CliMessages, BadDefineIsUsage) {
  Scratch s;
  const std::string ps = s.file("a.psh", kPs);
  auto r = run_cli("check -D 1X " + ps);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("1X"), std::string::npos) << r.err;
  EXPECT_EQ(run_cli("check -D =3 " + ps).exit_code, 2);
  EXPECT_EQ(run_cli("run -D '' --ps " + ps + " --size 1x1").exit_code, 2);
  EXPECT_EQ(run_cli("check -D GOOD=1 " + ps).exit_code, 0); // a good one still works
}

TEST(CliMessages, UnknownBuiltinTextureIsUsage) {
  Scratch s;
  const std::string ps =
      s.file("t.psh", "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n");
  auto r = run_cli("run --ps " + ps + " --size 2x2 --texture s0=builtin:nope");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("nope"), std::string::npos) << r.err;
}

TEST(CliMessages, ConstantOutsideTheStageIsRefused) {
  Scratch s;
  const std::string ps = s.file("c.psh", "ps_2_0\nmov oC0, c0\n");
  auto r = run_cli("run --ps " + ps + " --size 1x1 --const ps:c0=1,1,1,1 --const ps:c999=1,2,3,4");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("c999"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ps_2_0 has c0..c31"), std::string::npos) << r.err;
  // c31 is ps_2_0's last register: taken.
  EXPECT_EQ(run_cli("run --ps " + ps + " --size 1x1 --const ps:c0=1,1,1,1 --const ps:c31=1,2,3,4")
                .exit_code,
            0);
}

TEST(CliMessages, ConstBeyondFloatRangeSaysSo) {
  Scratch s;
  const std::string ps = s.file("c.psh", "ps_2_0\nmov oC0, c0\n");
  auto r = run_cli("run --ps " + ps + " --size 1x1 --const ps:c0=1e39,0,0,0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("1e39 is out of float range"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("needs four numbers"), std::string::npos) << r.err;
}

TEST(CliMessages, EmptyOutputNameIsUsage) {
  Scratch s;
  const std::string ps = s.file("a.psh", kPs);
  EXPECT_EQ(run_cli("fmt " + ps + " -o ''").exit_code, 2);
  EXPECT_EQ(run_cli("run --ps " + ps + " --size 1x1 -o ''").exit_code, 2);
  EXPECT_EQ(run_cli("assemble " + ps + " --output=").exit_code, 2);
  auto r = run_cli("spirv " + ps + " -o '' --json");
  EXPECT_EQ(r.exit_code, 2);
  nlohmann::json j;
  EXPECT_NO_THROW(j = nlohmann::json::parse(r.out)) << r.out;
  EXPECT_EQ(j["exit_code"], 2);
}

TEST(CliMessages, MalformedMemoryLimitIsAnError) {
  Scratch s;
  const std::string ps = s.file("a.psh", kPs);
  ::setenv("TIERLIFT_MEMORY_LIMIT", "4GiB", 1);
  auto r = run_cli("run --ps " + ps + " --size 1x1");
  auto fmt_run = run_cli("fmt " + ps); // a command that plans no memory is not concerned
  ::unsetenv("TIERLIFT_MEMORY_LIMIT");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("TIERLIFT_MEMORY_LIMIT='4GiB'"), std::string::npos) << r.err;
  EXPECT_EQ(fmt_run.exit_code, 0);
}

TEST(CliMessages, DisasmSaysWhatATextFileIs) {
  Scratch s;
  auto r = run_cli("disasm " + s.file("empty.bin", ""));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("this is an empty file, not a token stream"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("assembly text"), std::string::npos) << r.err;
  r = run_cli("disasm " + s.file("broken.h", "const DWORD g_ps[] = {\n  0xffff0200, 0x1g\n};\n"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("this is a C array that does not read"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("broken.h:2:"), std::string::npos) << r.err; // where it stops reading
  r = run_cli("disasm " + s.file("numbers.h", "{ 1, 2, 3 }\n"));
  EXPECT_NE(r.err.find("first value 0x00000001 is not a version token"), std::string::npos)
      << r.err;
  // Assembly text is still called that.
  r = run_cli("disasm " + s.file("a.psh", kPs));
  EXPECT_NE(r.err.find("this is assembly text"), std::string::npos) << r.err;
}

TEST(CliMessages, IncludeOfADeviceSaysWhatItIs) {
  Scratch s;
  const std::string ps = s.file("i.psh", "ps_2_0\n#include \"/dev/zero\"\nmov oC0, c0\n");
  auto r = run_cli("check " + ps);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("is not a regular file"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("cannot find"), std::string::npos) << r.err;
}

TEST(CliMessages, CarriageReturnAloneEndsALine) {
  Scratch s;
  // Classic Mac OS line endings: the error is on line 3, column 13 (r9).
  const std::string ps = s.file("cr.psh", "ps_2_0\r// comment\rmov oC0, r0, r9\r");
  auto r = run_cli("check " + ps);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("cr.psh:3:"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("cr.psh:1:"), std::string::npos) << r.err;
  // A valid CR-only listing is valid.
  EXPECT_EQ(run_cli("check " + s.file("ok.psh", "ps_2_0\r; c\rdef c0, 1, 1, 1, 1\rmov oC0, c0\r"))
                .exit_code,
            0);
}

TEST(CliMessages, ErrorsAreCappedAndTheCapIsAFlag) {
  Scratch s;
  // The validator stops at nothing: each `dcl t9` of a vs_2_0 is two errors (no such
  // register, and again for what it declares), 300 in all, plus oPos never written.
  std::string text = "vs_2_0\n";
  for (int i = 0; i < 150; ++i) text += "dcl t9\n";
  const std::string ps = s.file("many.vsh", text);
  auto r = run_cli("check " + ps);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(count(r.err, ": error: "), 100u) << r.err.substr(0, 400);
  EXPECT_NE(r.err.find("too many errors (100 shown); stopping"), std::string::npos);
  r = run_cli("check --max-errors 3 " + ps);
  EXPECT_EQ(count(r.err, ": error: "), 3u);
  r = run_cli("check --max-errors 0 " + ps);
  EXPECT_GE(count(r.err, ": error: "), 150u);
  EXPECT_EQ(r.err.find("too many errors"), std::string::npos);
  r = run_cli("check --max-errors 2 --json " + ps);
  nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_FALSE(j["diagnostics"].empty());
  size_t errors = 0;
  for (const nlohmann::json& d : j["diagnostics"]) errors += d["severity"] == "error";
  EXPECT_EQ(errors, 2u);
  EXPECT_EQ(j["diagnostics"].back()["rule"], "too-many-errors");
}

TEST(CliMessages, SceneErrorsUnderJsonArePositioned) {
  Scratch s;
  const std::string scene = s.file("bad.json", "{\n  \"glow\": {\"downsample\": 9}\n}\n");
  auto r = run_cli("glow --scene " + scene + " --json");
  EXPECT_EQ(r.exit_code, 1);
  nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_FALSE(j["diagnostics"].empty()) << r.out;
  const nlohmann::json& d = j["diagnostics"][0];
  EXPECT_EQ(d["line"], 2) << d;
  EXPECT_EQ(d["column"], 26) << d; // the 9
  EXPECT_EQ(d["file"], scene) << d;
  EXPECT_EQ(d["message"].get<std::string>().find('^'), std::string::npos) << d;
  EXPECT_EQ(d["message"].get<std::string>().find('\n'), std::string::npos) << d;
}

} // namespace
