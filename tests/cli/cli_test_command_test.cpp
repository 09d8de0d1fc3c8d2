// `tierlift test`: worker processes that die or hang cost one case, baselines, shards and
// their merge, exit codes.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_util.h"

namespace fs = std::filesystem;
using tierlift::test::read_all;

namespace {

struct TestRun {
  int exit_code = -1;
  std::string out;
};

// `env` goes before the binary (VAR=value ...).
TestRun tierlift_test(const std::string& env, const std::string& args) {
  fs::path log = fs::temp_directory_path() / ("tierlift_test_cmd_" + std::to_string(::getpid()));
  std::string cmd =
      env + " " + TIERLIFT_CLI_PATH + " test -q " + args + " >" + log.string() + " 2>&1";
  int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_all(log)};
}

fs::path fresh_dir(const std::string& name) {
  fs::path d =
      fs::temp_directory_path() / ("tierlift_testcmd_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& bytes) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
}

// id → verdict of results.jsonl (the last line of each id).
std::map<std::string, std::string> verdicts(const fs::path& dir) {
  std::map<std::string, std::string> out;
  std::ifstream in(dir / "results.jsonl");
  std::string line;
  while (std::getline(in, line)) {
    auto j = nlohmann::json::parse(line);
    out[j["id"].get<std::string>().substr(0, j["id"].get<std::string>().find('@'))] =
        j["verdict"].get<std::string>();
  }
  return out;
}

// Five small listings: four pixel, one vertex.
fs::path corpus(const std::string& name) {
  fs::path root = fresh_dir(name) / "c";
  write(root / "a.psh", "ps_2_0\ndef c0, 0.5, 0.25, 1, 1\nmov oC0, c0\n");
  write(root / "b.psh", "ps_2_0\ndcl t0\nadd r0, t0, c1\nmov oC0, r0\n");
  write(root / "c.psh", "ps_1_1\ntex t0\nmul r0, t0, v0\n");
  write(root / "d.psh", "ps_2_0\ndcl v0\nmul r0, v0, c2\nmov oC0, r0\n");
  write(root / "e.vsh", "vs_1_1\ndcl_position v0\ndcl_color v1\nmov oPos, v0\nmov oD0, v1\n");
  return root;
}

} // namespace

TEST(CliTest, CleanCorpusPassesEveryStageOnBothDevices) {
  fs::path root = corpus("clean"), out = root.parent_path() / "out";
  TestRun r = tierlift_test("", "-j 2 -o " + out.string() + " " + root.string());
  EXPECT_EQ(r.exit_code, 0) << r.out << read_all(out / "summary.md");
  auto v = verdicts(out);
  ASSERT_EQ(v.size(), 5u) << r.out;
  for (const auto& [id, verdict] : v) EXPECT_EQ(verdict, "pass") << id;
  for (const char* f : {"results.csv", "failures.csv", "junit.xml", "summary.md"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_NE(read_all(out / "summary.md").find("| diff | 5 | 0 | 0 | 0 |"), std::string::npos)
      << read_all(out / "summary.md");
}

TEST(CliTest, KilledHungAndTruncatedCostOneCaseEach) {
  fs::path root = corpus("contain"), out = root.parent_path() / "out";
  // A token stream cut short inside its first instruction (and not a whole DWORD).
  write(root / "f.pso", std::string("\x00\x02\xff\xff\x01\x00\x00", 7));
  // --timeout 10: the hang is endless, so any limit finds it; 3 s let an ordinary case of
  // this run time out too when the 2-core machine ran other tests beside it.
  TestRun r =
      tierlift_test("TIERLIFT_TEST_CRASH_ON=c/b.psh TIERLIFT_TEST_HANG_ON=c/d.psh",
                    "-j 2 --timeout 10 --no-rerun -o " + out.string() + " " + root.string());
  EXPECT_EQ(r.exit_code, 1) << r.out;
  auto v = verdicts(out);
  EXPECT_EQ(v["c/a.psh"], "pass");
  EXPECT_EQ(v["c/b.psh"], "crash");
  EXPECT_EQ(v["c/c.psh"], "pass");
  EXPECT_EQ(v["c/d.psh"], "timeout");
  EXPECT_EQ(v["c/e.vsh"], "pass");
  EXPECT_EQ(v["c/f.pso"], "fail");
  EXPECT_NE(read_all(out / "results.jsonl").find("signal 9"), std::string::npos);
  // Every failure names the command that reproduces it alone.
  EXPECT_NE(r.out.find("reproduce: tierlift test"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--only c/b.psh@"), std::string::npos) << r.out;
}

TEST(CliTest, BaselineNewFailureFixedAndUpdate) {
  fs::path root = corpus("baseline"), dir = root.parent_path();
  write(root / "bad.psh", "ps_2_0\nmov oC0, r7\n"); // r7 read before written
  TestRun first =
      tierlift_test("", "--check-only -o " + (dir / "o1").string() + " " + root.string());
  EXPECT_EQ(first.exit_code, 1) << first.out;
  fs::copy_file(dir / "o1" / "failures.csv", dir / "baseline.csv");
  TestRun second = tierlift_test("", "--check-only --baseline " + (dir / "baseline.csv").string() +
                                         " -o " + (dir / "o2").string() + " " + root.string());
  EXPECT_EQ(second.exit_code, 0) << second.out;
  // A skipped case never runs.
  write(dir / "skips.txt", "c/a\\.psh@\n");
  TestRun skipped = tierlift_test("", "--check-only --skips " + (dir / "skips.txt").string() +
                                          " -o " + (dir / "o4").string() + " " + root.string());
  EXPECT_EQ(verdicts(dir / "o4")["c/a.psh"], "skip");
  // --update-baseline writes this run's failures: bad.psh, failing validation, in place of
  // what the file held.
  write(dir / "baseline.csv", "id,verdict,stage\nold@0,fail,parse\n");
  TestRun update = tierlift_test("", "--check-only --update-baseline --baseline " +
                                         (dir / "baseline.csv").string() + " -o " +
                                         (dir / "o5").string() + " " + root.string());
  EXPECT_EQ(update.exit_code, 0) << update.out;
  const std::string baseline = read_all(dir / "baseline.csv");
  EXPECT_EQ(baseline.substr(0, 27), "id,verdict,stage\nc/bad.psh@") << baseline;
  EXPECT_TRUE(baseline.ends_with(",fail,validate\n")) << baseline;
  EXPECT_EQ(std::count(baseline.begin(), baseline.end(), '\n'), 2);
}

TEST(CliTest, FixedBaselineFailureExitsOne) {
  fs::path root = corpus("fixed"), dir = root.parent_path();
  TestRun list = tierlift_test("", "--list " + root.string());
  const std::string a_id = list.out.substr(0, list.out.find('\n'));
  ASSERT_EQ(a_id.substr(0, 8), "c/a.psh@") << list.out;
  write(dir / "baseline.csv", "id,verdict,stage\n" + a_id + ",fail,diff\n");
  TestRun r = tierlift_test("", "--check-only --baseline " + (dir / "baseline.csv").string() +
                                    " -o " + (dir / "o").string() + " " + root.string());
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("FIXED " + a_id), std::string::npos) << r.out;
}

// Shards balanced by the single run's times (--shard-costs) still merge into the single run;
// a cost file without --shard, or one that cannot be read, is a usage or I/O error.
TEST(CliTest, CostBalancedShardsMergeIntoTheSingleRun) {
  fs::path root = corpus("cost_shards"), dir = root.parent_path();
  write(root / "bad.psh", "ps_2_0\nmov oC0, r7\n");
  const std::string common = "--check-only --no-rerun " + root.string();
  tierlift_test("", "-o " + (dir / "one").string() + " " + common);
  const std::string costs = " --shard-costs " + (dir / "one" / "results.jsonl").string();
  std::string shard_dirs;
  for (int i = 0; i < 2; ++i) {
    const std::string d = (dir / ("c" + std::to_string(i))).string();
    tierlift_test("", "--shard " + std::to_string(i) + "/2" + costs + " -o " + d + " " + common);
    shard_dirs += " " + d;
  }
  TestRun merge = tierlift_test("", "merge" + shard_dirs + " -o " + (dir / "merged").string());
  EXPECT_EQ(merge.exit_code, 1) << merge.out;
  for (const char* f : {"results.csv", "failures.csv", "summary.md"})
    EXPECT_EQ(read_all(dir / "merged" / f), read_all(dir / "one" / f)) << f;
  EXPECT_EQ(tierlift_test("", costs.substr(1) + " " + common).exit_code, 2);
  EXPECT_EQ(
      tierlift_test("", "--shard 0/2 --shard-costs " + (dir / "none.jsonl").string() + " " + common)
          .exit_code,
      2);
}

TEST(CliTest, ShardsMergeIntoTheSingleRunAndResumeFinishesARun) {
  fs::path root = corpus("shards"), dir = root.parent_path();
  write(root / "bad.psh", "ps_2_0\nmov oC0, r7\n");
  const std::string common = "--check-only --no-rerun " + root.string();
  tierlift_test("", "-o " + (dir / "one").string() + " " + common);
  std::string shard_dirs;
  for (int i = 0; i < 3; ++i) {
    const std::string d = (dir / ("s" + std::to_string(i))).string();
    tierlift_test("", "--shard " + std::to_string(i) + "/3 -o " + d + " " + common);
    shard_dirs += " " + d;
  }
  TestRun merge = tierlift_test("", "merge" + shard_dirs + " -o " + (dir / "merged").string());
  EXPECT_EQ(merge.exit_code, 1) << merge.out; // bad.psh fails in both
  for (const char* f : {"results.csv", "failures.csv", "summary.md"})
    EXPECT_EQ(read_all(dir / "merged" / f), read_all(dir / "one" / f)) << f;
  // A run cut short: resume runs only what its results.jsonl lacks.
  fs::create_directories(dir / "resumed");
  std::ifstream in(dir / "one" / "results.jsonl");
  std::string line;
  std::getline(in, line);
  std::ofstream(dir / "resumed" / "results.jsonl") << line << "\n";
  tierlift_test("", "--resume -o " + (dir / "resumed").string() + " " + common);
  EXPECT_EQ(read_all(dir / "resumed" / "results.csv"), read_all(dir / "one" / "results.csv"));
  EXPECT_EQ(tierlift_test("", "--shard 3/3 " + common).exit_code, 2);
}

// A baseline kept as the output folder's own failures.csv (or costs as its results.jsonl)
// would be replaced by this run's: the run is refused before it writes, and the file stays.
TEST(CliTest, AnInputInTheOutputFolderIsRefusedAndKept) {
  fs::path root = corpus("own_input"), out = root.parent_path() / "out";
  tierlift_test("", "--check-only -o " + out.string() + " " + root.string());
  const std::string baseline = "id,verdict,stage\nc/old.psh@0,fail,parse\n";
  write(out / "failures.csv", baseline);
  const std::string jsonl = read_all(out / "results.jsonl");
  TestRun r = tierlift_test("", "--check-only --baseline " + (out / "failures.csv").string() +
                                    " -o " + out.string() + " " + root.string());
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("failures.csv: refusing to run"), std::string::npos) << r.out;
  EXPECT_EQ(read_all(out / "failures.csv"), baseline);
  r = tierlift_test("", "--check-only --shard 0/2 --shard-costs " +
                            (out / "results.jsonl").string() + " -o " + out.string() + " " +
                            root.string());
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_EQ(read_all(out / "results.jsonl"), jsonl);
  r = tierlift_test("", "merge " + out.string() + " -o " + (out.parent_path() / "m").string());
  r = tierlift_test("", "merge " + out.string() + " -o " + (out.parent_path() / "m").string() +
                            " --baseline " + (out.parent_path() / "m" / "failures.csv").string());
  EXPECT_EQ(r.exit_code, 2) << r.out;
}

// `-o` naming a folder of the user's own files (here a summary.md of theirs) is refused, and
// the file stays.
TEST(CliTest, AFolderOfOtherFilesIsNotWrittenInto) {
  fs::path root = corpus("foreign"), out = root.parent_path() / "notes";
  write(out / "summary.md", "my notes\n");
  TestRun r = tierlift_test("", "--check-only -o " + out.string() + " " + root.string());
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("no results.jsonl"), std::string::npos) << r.out;
  EXPECT_EQ(read_all(out / "summary.md"), "my notes\n");
  EXPECT_FALSE(fs::exists(out / "results.jsonl"));
}
