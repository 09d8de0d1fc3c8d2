// io::OutputFolder: a folder of outputs is complete or untouched. A new folder appears whole
// at commit; into one that exists the run's files go in, the last run's stale ones go out,
// the user's stay; an input is never replaced or removed; destruction without commit and
// SIGTERM leave nothing behind.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "temp_dir.h"
#include "tierlift/io/output_file.h"
#include "tierlift/io/output_folder.h"

namespace fs = std::filesystem;
namespace io = tierlift::io;

namespace {

struct TempDir : tierlift::test::TempDir {
  TempDir() : tierlift::test::TempDir("io_folder") {}
};

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Every name in `dir`, hidden ones included, sorted.
std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// One run writing `files` (name → text) into `dir`, committed.
void run_writing(const std::string& dir,
                 const std::vector<std::pair<std::string, std::string>>& files,
                 const std::vector<std::string>& inputs = {}) {
  io::OutputFolder out(dir, inputs, "test");
  ASSERT_TRUE(out.status()) << out.status().message();
  for (const auto& [name, text] : files) {
    tierlift::ir::Result<std::string> path = out.path(name);
    ASSERT_TRUE(path) << path.message();
    ASSERT_TRUE(io::write_output(*path, text));
  }
  tierlift::ir::Result<std::vector<std::string>> done = out.commit();
  ASSERT_TRUE(done) << done.message();
  ASSERT_EQ(done->size(), files.size());
  EXPECT_EQ((*done)[0], dir + "/" + files[0].first);
}

} // namespace

TEST(OutputFolder, ANewFolderAppearsWholeAtCommit) {
  TempDir dir;
  const std::string target = dir / "nested/out";
  io::OutputFolder out(target, {}, "test");
  ASSERT_TRUE(out.status()) << out.status().message();
  tierlift::ir::Result<std::string> a = out.path("a.txt");
  ASSERT_TRUE(a);
  ASSERT_TRUE(io::write_output(*a, "A"));
  // Before the commit: only the hidden temporary folder, in the nearest folder there is.
  EXPECT_FALSE(fs::exists(target));
  ASSERT_EQ(entries(dir.path()).size(), 1u);
  EXPECT_TRUE(entries(dir.path())[0].starts_with(".out.tmp")) << entries(dir.path())[0];
  ASSERT_TRUE(out.commit());
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"nested"});
  EXPECT_EQ(entries(target), (std::vector<std::string>{".tierlift-written-test", "a.txt"}));
  EXPECT_EQ(slurp(target + "/a.txt"), "A");
}

TEST(OutputFolder, DestroyedUncommittedLeavesNothing) {
  TempDir dir;
  {
    io::OutputFolder out(dir / "out", {}, "test");
    ASSERT_TRUE(io::write_output(*out.path("a.txt"), "A"));
  }
  EXPECT_TRUE(entries(dir.path()).empty());
  fs::create_directories(dir / "kept");
  std::ofstream(dir / "kept/mine.txt") << "mine";
  {
    io::OutputFolder out(dir / "kept", {}, "test");
    ASSERT_TRUE(io::write_output(*out.path("mine.txt"), "theirs"));
  }
  EXPECT_EQ(entries(dir / "kept"), std::vector<std::string>{"mine.txt"});
  EXPECT_EQ(slurp(dir / "kept/mine.txt"), "mine");
}

TEST(OutputFolder, StaleOutputsGoTheUsersFilesStay) {
  TempDir dir;
  const std::string target = dir / "out";
  fs::create_directories(target);
  std::ofstream(target + "/notes.txt") << "mine";
  run_writing(target, {{"a.png", "1"}, {"b.png", "1"}});
  run_writing(target, {{"a.png", "2"}});
  EXPECT_EQ(entries(target),
            (std::vector<std::string>{".tierlift-written-test", "a.png", "notes.txt"}));
  EXPECT_EQ(slurp(target + "/a.png"), "2");
  EXPECT_EQ(slurp(target + "/notes.txt"), "mine");
  // Another kind of run (another tag) leaves this one's files alone.
  {
    io::OutputFolder other(target, {}, "other");
    ASSERT_TRUE(io::write_output(*other.path("c.txt"), "c"));
    ASSERT_TRUE(other.commit());
  }
  EXPECT_TRUE(fs::exists(target + "/a.png"));
}

TEST(OutputFolder, AnInputIsNeitherReplacedNorRemoved) {
  TempDir dir;
  const std::string target = dir / "out";
  run_writing(target, {{"a.png", "1"}, {"b.png", "1"}});
  // b.png, an output of the last run, is now an input of this one.
  const std::vector<std::string> inputs{target + "/b.png"};
  {
    io::OutputFolder out(target, inputs, "test");
    tierlift::ir::Result<std::string> refused = out.path("b.png");
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.message().find("refusing to write over"), std::string::npos)
        << refused.message();
    EXPECT_FALSE(out.commit()) << "a refused name fails the whole folder";
  }
  EXPECT_EQ(slurp(target + "/b.png"), "1");
  run_writing(target, {{"a.png", "2"}}, inputs); // b.png is stale, but an input: kept
  EXPECT_EQ(slurp(target + "/b.png"), "1");
}

TEST(OutputFolder, AFileWhereTheFolderShouldBeIsRefused) {
  TempDir dir;
  std::ofstream(dir / "out") << "a file";
  io::OutputFolder out(dir / "out", {}, "test");
  EXPECT_NE(out.status().message().find("exists and is not a folder"), std::string::npos)
      << out.status().message();
  EXPECT_FALSE(out.path("a.txt"));
  EXPECT_EQ(slurp(dir / "out"), "a file");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out"});
  io::OutputFolder dash("-", {}, "test");
  EXPECT_FALSE(dash.status());
}

// A run ended by SIGTERM, its temporary folder holding a finished file and an AtomicFile's
// half-written one: nothing of it remains, in a new DIR or in one that exists.
TEST(OutputFolder, SigtermRemovesTheTemporaryFolder) {
  TempDir dir;
  fs::create_directories(dir / "existing");
  std::ofstream(dir / "existing/mine.txt") << "mine";
  for (const std::string& target : {dir / "new", dir / "existing"}) {
    pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      io::OutputFolder out(target, {}, "test");
      if (!out.status()) ::_exit(3);
      if (!io::write_output(*out.path("done.png"), "done")) ::_exit(4);
      io::AtomicFile half(*out.path("half.png"));
      if (!half.write("half")) ::_exit(5);
      ::raise(SIGTERM);
      ::_exit(6); // not reached
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << WEXITSTATUS(status);
    EXPECT_EQ(WTERMSIG(status), SIGTERM);
  }
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"existing"});
  EXPECT_EQ(entries(dir / "existing"), std::vector<std::string>{"mine.txt"});
}
