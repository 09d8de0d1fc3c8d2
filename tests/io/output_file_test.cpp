// io::write_output and io::AtomicFile: no user file is ever lost. Symbolic links are
// followed, FIFOs and devices written through, inputs refused, and a signal removes the
// temporary file.
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "temp_dir.h"
#include "tierlift/io/output_file.h"

namespace fs = std::filesystem;
namespace io = tierlift::io;
namespace ir = tierlift::ir;

namespace {

// A fresh folder per test, removed afterwards.
struct TempDir : tierlift::test::TempDir {
  TempDir() : tierlift::test::TempDir("io_write") {}
};

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void put(const std::string& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

} // namespace

TEST(WriteOutput, CreatesAndReplacesLeavingNoTemporary) {
  TempDir dir;
  ASSERT_EQ(io::write_output(dir / "out.bin", "first").message(), "");
  EXPECT_EQ(slurp(dir / "out.bin"), "first");
  ::chmod((dir / "out.bin").c_str(), 0640);
  ASSERT_EQ(io::write_output(dir / "out.bin", "second").message(), "");
  EXPECT_EQ(slurp(dir / "out.bin"), "second");
  struct stat st {};
  ASSERT_EQ(::stat((dir / "out.bin").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0640u) << "the replaced file keeps its permissions";
  EXPECT_EQ(dir.names(), std::vector<std::string>{"out.bin"});
}

TEST(WriteOutput, FollowsASymbolicLinkAndKeepsIt) {
  TempDir dir;
  put(dir / "real.txt", "old");
  fs::create_symlink("real.txt", dir / "link.txt");
  ASSERT_EQ(io::write_output(dir / "link.txt", "new").message(), "");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(slurp(dir / "real.txt"), "new");
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"link.txt", "real.txt"}));
}

TEST(WriteOutput, ADanglingLinkCreatesItsTarget) {
  TempDir dir;
  fs::create_symlink("made.txt", dir / "link.txt");
  ASSERT_EQ(io::write_output(dir / "link.txt", "x").message(), "");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(slurp(dir / "made.txt"), "x");
}

TEST(WriteOutput, WritesThroughAFifo) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  std::string got;
  std::thread reader([&] { got = slurp(dir / "pipe"); });
  EXPECT_EQ(io::write_output(dir / "pipe", "through").message(), "");
  reader.join();
  EXPECT_EQ(got, "through");
  EXPECT_TRUE(fs::is_fifo(dir / "pipe")) << "the FIFO must not be replaced by a regular file";
}

TEST(WriteOutput, WritesThroughACharacterDevice) {
  EXPECT_EQ(io::write_output("/dev/null", "gone").message(), "");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(WriteOutput, DirectoriesAndMissingFoldersFailWithoutLeftovers) {
  TempDir dir;
  EXPECT_NE(io::write_output(dir.path().string(), "x").message().find("is a directory"),
            std::string::npos);
  std::string err = io::write_output(dir / "no/such/folder/out.bin", "x").message();
  EXPECT_NE(err.find("no/such/folder/out.bin"), std::string::npos) << err;
  EXPECT_TRUE(dir.names().empty());
}

TEST(WriteOutput, ReadOnlyFolderFailsWithoutLeftovers) {
  // root ignores permission bits; /proc/self is read-only for everyone.
  std::string target = "/proc/self/tierlift-out.bin";
  TempDir dir;
  if (::geteuid() != 0) {
    fs::create_directories(dir / "ro");
    ::chmod((dir / "ro").c_str(), 0555);
    target = dir / "ro/out.bin";
  }
  EXPECT_NE(io::write_output(target, "x").message(), "");
  EXPECT_FALSE(fs::exists(target));
  if (::geteuid() != 0) {
    EXPECT_TRUE(fs::is_empty(dir / "ro"));
    ::chmod((dir / "ro").c_str(), 0755);
  }
}

TEST(SameFile, ComparesDeviceAndInodeNotNames) {
  TempDir dir;
  put(dir / "a.psh", "ps_2_0\n");
  put(dir / "b.psh", "ps_2_0\n"); // same bytes, another file
  fs::create_hard_link(dir / "a.psh", dir / "hard.psh");
  fs::create_symlink(dir / "a.psh", dir / "soft.psh");
  EXPECT_TRUE(io::same_file(dir / "a.psh", dir / "hard.psh"));
  EXPECT_TRUE(io::same_file(dir / "a.psh", dir / "soft.psh"));
  EXPECT_TRUE(io::same_file(dir / "a.psh", dir.path().string() + "/./a.psh"));
  EXPECT_FALSE(io::same_file(dir / "a.psh", dir / "b.psh"));
  EXPECT_FALSE(io::same_file(dir / "a.psh", dir / "missing.psh"));
  EXPECT_FALSE(io::same_file("-", "-"));
  std::vector<std::string> inputs{dir / "b.psh", dir / "a.psh"};
  EXPECT_NE(io::refuse_if_input(dir / "hard.psh", inputs).message().find("refusing"),
            std::string::npos);
  EXPECT_EQ(io::refuse_if_input(dir / "new.bin", inputs).message(), "");
  EXPECT_TRUE(io::refuse_if_input(dir / "new.bin", inputs).ok());
  ir::Status refused = io::refuse_if_input(dir / "a.psh", inputs);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.diagnostics()[0].rule, "write");
  EXPECT_EQ(refused.diagnostics()[0].subject, std::string(dir / "a.psh"));
}

TEST(AtomicFile, SigtermRemovesTheTemporaryFile) {
  TempDir dir;
  put(dir / "out.bin", "old");
  pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    io::AtomicFile f(dir / "out.bin");
    if (!f.status() || !f.write("half of it")) ::_exit(3);
    if (!fs::exists(f.temp_path())) ::_exit(4);
    ::raise(SIGTERM); // as a user's kill during a long write
    ::_exit(5);       // not reached: SIGTERM still ends the process
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(dir.names(), std::vector<std::string>{"out.bin"});
  EXPECT_EQ(slurp(dir / "out.bin"), "old");
}

TEST(AtomicFile, DestroyedUncommittedLeavesTheOldFile) {
  TempDir dir;
  put(dir / "out.bin", "old");
  {
    io::AtomicFile f(dir / "out.bin");
    ASSERT_TRUE(f.status()) << f.status().message();
    ASSERT_TRUE(f.write("new"));
  }
  EXPECT_EQ(dir.names(), std::vector<std::string>{"out.bin"});
  EXPECT_EQ(slurp(dir / "out.bin"), "old");
}
