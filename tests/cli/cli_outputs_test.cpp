// Nothing lost through the outputs (issue 32, items 1–4), through the real binary:
//  - an -o onto a file the listing #includes, or onto a scene's input, is refused (exit 2)
//    and the file is left as it was;
//  - fmt refuses a listing whose directives or macros it would drop (exit 1, with a caret);
//  - glow -o DIR leaves DIR whole: stale outputs of an earlier run go, the user's files stay,
//    and an interrupted run leaves neither a temporary folder nor an empty DIR;
//  - a failed write to standard output (a full device, a closed descriptor) is exit 2.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_test_util.h"
#include "temp_dir.h"

using tierlift::test::read_all;
using tierlift::test::run_cli;
namespace fs = std::filesystem;

extern char** environ;

namespace {

struct Scratch : tierlift::test::TempDir {
  Scratch() : tierlift::test::TempDir("cli_outputs") {}
};

const std::string kMain = "ps_2_0\n#include \"c.inc\"\nmov oC0, r0\n";
const std::string kInc = "def c0,1,0,0,1\nmov r0, c0\n";
const std::string kPlain = "ps_2_0\ndef c0, 1, 0, 0, 1\nmov oC0, c0\n";

// `tierlift ARGS` with standard output sent where `stdout_redirect` says (">/dev/full",
// ">&-"); standard error captured. The exit code (-1 when killed) and standard error.
tierlift::test::CliResult run_redirected(const std::string& args,
                                         const std::string& stdout_redirect) {
  Scratch s;
  const std::string err = s.file("stderr.txt");
  const std::string cmd =
      std::string(TIERLIFT_CLI_PATH) + " " + args + " </dev/null " + stdout_redirect + " 2>" + err;
  const int status = std::system(cmd.c_str());
  tierlift::test::CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_all(err);
  return r;
}

// Names in `dir` (hidden ones too), sorted.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace

// Item 1: the issue's reproducer, and fmt and spirv the same way.
TEST(CliOutputs, AnIncludedFileIsNeverAnOutput) {
  Scratch s;
  const std::string main = s.file("m.psh", kMain), inc = s.file("c.inc", kInc);
  for (const std::string& cmd : {"assemble " + main + " -o " + inc, "fmt " + main + " -o " + inc,
                                 "spirv " + main + " -o " + inc}) {
    auto r = run_cli(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.err;
    EXPECT_NE(r.err.find("refusing to write over " + inc + ", which " + main + " #includes"),
              std::string::npos)
        << cmd << "\n"
        << r.err;
    EXPECT_EQ(read_all(inc), kInc) << cmd;
  }
  EXPECT_EQ(s.names(), (std::vector<std::string>{"c.inc", "m.psh"})) << "a temporary was left";
}

// Through another include, another name for the file (a hard link) and --json.
TEST(CliOutputs, AnIncludeOfAnIncludeIsRefusedUnderAnyName) {
  Scratch s;
  const std::string main = s.file("m.psh", "ps_2_0\n#include \"a.inc\"\nmov oC0, r0\n");
  s.file("a.inc", "#include \"b.inc\"\n");
  const std::string b = s.file("b.inc", kInc);
  fs::create_hard_link(b, s.file("alias.bin"));
  auto r = run_cli("assemble --json " + main + " -o " + s.file("alias.bin"));
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("#includes (the same file)"), std::string::npos) << r.out;
  EXPECT_EQ(read_all(b), kInc);
  // An include in the branch not taken is not read, so it is no input: the write goes on.
  const std::string other = s.file("o.psh", "ps_2_0\n#ifdef NOPE\n#include \"x.bin\"\n#endif\n"
                                            "def c0, 1, 0, 0, 1\nmov oC0, c0\n");
  EXPECT_EQ(run_cli("assemble " + other + " -o " + s.file("x.bin")).exit_code, 0);
}

// Item 1 for scenes: an image the scene reads (here its glow image, the previous run's
// output) is never replaced by glow -o.
TEST(CliOutputs, GlowNeverReplacesAnImageTheSceneReads) {
  Scratch s;
  const fs::path sign = fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "scenes" / "sign.png";
  fs::copy_file(sign, s.file("sign.png"));
  s.file("first.json", R"({"image": "sign.png", "glow": {"downsample": 2, "format": "rgba8"}})");
  const std::string out = s.file("out");
  auto first = run_cli("glow -q --backend analytic --scene " + s.file("first.json") + " -o " + out);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const std::string reused = out + "/scene-analytic.png";
  const std::string before = read_all(reused);
  ASSERT_FALSE(before.empty());
  s.file("second.json", R"({"image": "sign.png", "glow_image": "out/scene-analytic.png",
                            "glow": {"downsample": 2, "format": "rgba8"}})");
  auto second =
      run_cli("glow -q --backend analytic --scene " + s.file("second.json") + " -o " + out);
  EXPECT_EQ(second.exit_code, 2) << second.err;
  EXPECT_NE(second.err.find("refusing to write over"), std::string::npos) << second.err;
  EXPECT_EQ(read_all(reused), before);
}

// Item 2: a directive or a -D macro is refused at its position, with the caret; a listing
// without them (or a -D it never uses) is formatted as before.
TEST(CliOutputs, FmtRefusesWhatItWouldDrop) {
  Scratch s;
  s.file("c.inc", kInc);
  auto inc = run_cli("fmt " + s.file("m.psh", kMain));
  EXPECT_EQ(inc.exit_code, 1) << inc.err;
  EXPECT_NE(inc.err.find("m.psh:2:1: error: fmt cannot keep #include"), std::string::npos)
      << inc.err;
  EXPECT_NE(inc.err.find("#include \"c.inc\"\n    ^~~~~~~~"), std::string::npos) << inc.err;
  EXPECT_TRUE(inc.out.empty()) << inc.out;

  const std::string branches = "ps_2_0\ndef c0, 1, 0, 0, 1\n#ifdef RED\nmov r0, c0\n#else\n"
                               "mov r0, c0.y\n#endif\nmov oC0, r0\n";
  auto cond = run_cli("fmt " + s.file("b.psh", branches));
  EXPECT_EQ(cond.exit_code, 1);
  EXPECT_NE(cond.err.find("b.psh:3:1: error: fmt cannot keep #ifdef"), std::string::npos)
      << cond.err;

  const std::string macro = s.file("d.psh", "ps_2_0\ndef c0, 1, 0, 0, 1\nmov oC0, COLOUR\n");
  auto use = run_cli("fmt -D COLOUR=c0 " + macro + " -o " + s.file("out.psh"));
  EXPECT_EQ(use.exit_code, 1);
  EXPECT_NE(use.err.find("d.psh:3:10: error: fmt cannot keep macro COLOUR"), std::string::npos)
      << use.err;
  EXPECT_FALSE(fs::exists(s.file("out.psh")));

  auto unused = run_cli("fmt -D UNUSED=1 " + s.file("p.psh", kPlain));
  EXPECT_EQ(unused.exit_code, 0) << unused.err;
  EXPECT_NE(unused.out.find("mov oC0, c0"), std::string::npos) << unused.out;
}

// Item 4: standard output full or closed is exit 2 with a message, for the text, the JSON
// document, and the token stream written through -o -; a large text (past stdio's buffer,
// where fmt::print itself fails) too.
TEST(CliOutputs, AFailedWriteToStandardOutputIsExitTwo) {
  Scratch s;
  const std::string in = s.file("p.psh", kPlain);
  // Past stdio's buffer, so that a write fails while the command still prints.
  std::string big = "ps_2_0\n";
  for (int i = 0; i < 200; ++i) big += "// " + std::string(70, 'x') + "\n";
  big += "def c0, 1, 0, 0, 1\nmov oC0, c0\n";
  const std::string large = s.file("large.psh", big);
  ASSERT_EQ(run_cli("assemble " + in + " -o " + s.file("p.bin")).exit_code, 0);
  for (const std::string& args :
       {"fmt " + in, "fmt --json " + in, "check " + in, "check --json " + in,
        "assemble " + in + " -o -", "disasm " + s.file("p.bin"), "disasm --json " + s.file("p.bin"),
        "fmt " + large, "fmt --json " + large, std::string("listings")}) {
    for (const char* redirect : {">/dev/full", ">&-"}) {
      auto r = run_redirected(args, redirect);
      EXPECT_EQ(r.exit_code, 2) << args << " " << redirect << "\n" << r.err;
      EXPECT_NE(r.err.find("write failed"), std::string::npos) << args << " " << redirect << "\n"
                                                               << r.err;
    }
  }
  // Nothing written to standard output: nothing to fail.
  auto quiet = run_redirected("assemble " + in + " -o " + s.file("x.bin"), ">&-");
  EXPECT_EQ(quiet.exit_code, 0) << quiet.err;
}

// Item 3: into a folder that exists, the outputs of an earlier run that this run does not
// write are removed (the .pfm of an rgba32f run, when the next is rgba8), the user's own
// file stays.
TEST(CliOutputs, GlowFolderHoldsOneRunAndTheUsersFiles) {
  Scratch s;
  const std::string png =
      (fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "scenes" / "sign.png").string();
  const std::string out = s.file("out");
  fs::create_directories(out);
  std::ofstream(out + "/notes.txt") << "mine";
  const std::string base = "glow -q --backend analytic --image " + png + " -o " + out;
  auto f32 = run_cli(base + " --format rgba32f");
  ASSERT_EQ(f32.exit_code, 0) << f32.err;
  EXPECT_TRUE(fs::exists(out + "/final-analytic.pfm"));
  auto u8 = run_cli(base + " --format rgba8");
  ASSERT_EQ(u8.exit_code, 0) << u8.err;
  EXPECT_EQ(entries(out),
            (std::vector<std::string>{".tierlift-written-glow", "final-analytic.png",
                                      "glow-analytic.png", "notes.txt", "scene-analytic.png"}));
  EXPECT_EQ(read_all(out + "/notes.txt"), "mine");
}

// Item 3: SIGTERM while glow runs (its temporary folder exists) leaves the parent folder as
// it was: no temporary folder, no DIR.
TEST(CliOutputs, AnInterruptedGlowLeavesNothing) {
  Scratch s;
  const std::string out = s.file("out");
  std::vector<std::string> args = {
      TIERLIFT_CLI_PATH, "glow", "-q", "--backend", "cpu", "--threads", "1",
      "--frames",        "50",   "-o", out};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  // Wait for the temporary folder: the run is under way and has something to clean up.
  bool seen = false;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!seen && std::chrono::steady_clock::now() < until) {
    for (const std::string& n : entries(s.path())) seen = seen || n.starts_with(".out.tmp");
    if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_TRUE(seen) << "glow never made its temporary folder";
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status))
      << "glow finished before the signal; exit " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_TRUE(entries(s.path()).empty()) << entries(s.path()).front();
}
