// io::read_bounded: sizes are checked before reading, pipes and devices are read for at most
// cap + 1 bytes, and every refusal names the cap.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "temp_dir.h"
#include "tierlift/io/bounded_read.h"

namespace fs = std::filesystem;
using tierlift::io::ReadCap;

namespace {

// A fresh folder per test, removed afterwards.
struct TempDir : tierlift::test::TempDir {
  TempDir() : tierlift::test::TempDir("io_read") {}
};

constexpr ReadCap kTiny{16, "test input"};

// io::read_bounded with its failure's message in `error`, so each test can look at the text.
std::optional<std::string> read_capped(const std::string& path, const ReadCap& cap,
                                       std::string& error,
                                       const tierlift::io::PrefixCheck& check = nullptr) {
  tierlift::ir::Result<std::string> r = tierlift::io::read_bounded(path, cap, check);
  if (!r) {
    error = r.message();
    return std::nullopt;
  }
  return std::move(r).value();
}

} // namespace

TEST(BoundedRead, ReadsAFileUpToTheCapExactly) {
  TempDir dir;
  std::string error;
  auto at_cap = read_capped(dir.file("a", std::string(16, 'x')), kTiny, error);
  ASSERT_TRUE(at_cap) << error;
  EXPECT_EQ(*at_cap, std::string(16, 'x'));
  auto empty = read_capped(dir.file("e", ""), kTiny, error);
  ASSERT_TRUE(empty) << error;
  EXPECT_TRUE(empty->empty());
}

TEST(BoundedRead, RefusesAFileOneByteOverTheCapNamingIt) {
  TempDir dir;
  std::string error;
  EXPECT_FALSE(read_capped(dir.file("a", std::string(17, 'x')), kTiny, error));
  EXPECT_NE(error.find("too large for a test input"), std::string::npos) << error;
  EXPECT_NE(error.find("16 bytes"), std::string::npos) << error;
}

TEST(BoundedRead, RefusesDevZeroAtTheCap) {
  std::string error;
  const ReadCap cap{uint64_t{1} << 20, "listing"};
  EXPECT_FALSE(read_capped("/dev/zero", cap, error));
  EXPECT_NE(error.find("/dev/zero: too large for a listing: the cap is 1 MiB"), std::string::npos)
      << error;
}

TEST(BoundedRead, StopsReadingAnEndlessPipeAfterCapPlusOneBytes) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  pid_t writer = ::fork();
  ASSERT_GE(writer, 0);
  if (writer == 0) { // writes until the reader goes away (SIGPIPE ends it)
    ::close(fds[0]);
    char block[4096] = {};
    for (;;)
      if (::write(fds[1], block, sizeof block) < 0) ::_exit(0);
  }
  ::close(fds[1]);
  std::string error;
  auto r = read_capped("/dev/fd/" + std::to_string(fds[0]), ReadCap{100000, "scene"}, error);
  ::close(fds[0]);
  int status = 0;
  ::waitpid(writer, &status, 0);
  EXPECT_FALSE(r);
  EXPECT_NE(error.find("too large for a scene"), std::string::npos) << error;
}

TEST(BoundedRead, ReadsAShortPipeWhole) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ASSERT_EQ(::write(fds[1], "ps_2_0\n", 7), 7);
  ::close(fds[1]);
  std::string error;
  auto r = read_capped("/dev/fd/" + std::to_string(fds[0]), kTiny, error);
  ::close(fds[0]);
  ASSERT_TRUE(r) << error;
  EXPECT_EQ(*r, "ps_2_0\n");
}

TEST(BoundedRead, DirectoriesAndMissingFilesAreErrors) {
  TempDir dir;
  std::string error;
  EXPECT_FALSE(read_capped(dir.path().string(), kTiny, error));
  EXPECT_NE(error.find("is a directory"), std::string::npos) << error;
  EXPECT_FALSE(read_capped((dir.path() / "missing").string(), kTiny, error));
  EXPECT_NE(error.find("cannot read"), std::string::npos) << error;
}

TEST(BoundedRead, PrefixCheckStopsBeforeTheRest) {
  std::string error;
  std::string seen;
  auto check = [&](std::string_view first) -> tierlift::ir::Status {
    seen = std::string(first.substr(0, 4));
    return tierlift::ir::fail("", "image", "no signature");
  };
  // /dev/zero with a 1 GiB cap: refused from its first block, long before the cap.
  EXPECT_FALSE(read_capped("/dev/zero", ReadCap{uint64_t{1} << 30, "image file"}, error, check));
  EXPECT_EQ(error, "/dev/zero: no signature");
  EXPECT_EQ(seen, std::string(4, '\0'));
  // The check's rule is kept (a file of the wrong kind is not an I/O problem); a file that
  // cannot be opened stays "io".
  auto wrong_kind =
      tierlift::io::read_bounded("/dev/zero", ReadCap{uint64_t{1} << 30, "image file"}, check);
  ASSERT_FALSE(wrong_kind);
  EXPECT_EQ(wrong_kind.diagnostics().at(0).rule, "image");
  auto missing = tierlift::io::read_bounded("/nonexistent/tierlift-input", kTiny, check);
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.diagnostics().at(0).rule, "io");
}

TEST(BoundedRead, FormatsCapsInBinaryUnits) {
  EXPECT_EQ(tierlift::io::format_size(uint64_t{4} << 20), "4 MiB");
  EXPECT_EQ(tierlift::io::format_size(uint64_t{1} << 30), "1 GiB");
  EXPECT_EQ(tierlift::io::format_size(3000), "3000 bytes");
  EXPECT_EQ(tierlift::io::format_size(2048), "2 KiB");
}

TEST(BoundedRead, AFailureIsAnIoDiagnosticAboutThePath) {
  auto r = tierlift::io::read_bounded("/nonexistent/tierlift-input", kTiny);
  ASSERT_FALSE(r);
  ASSERT_EQ(r.diagnostics().size(), 1u);
  const tierlift::ir::Diagnostic& d = r.diagnostics()[0];
  EXPECT_EQ(d.severity, tierlift::ir::Severity::Error);
  EXPECT_EQ(d.rule, "io");
  EXPECT_EQ(d.subject, "/nonexistent/tierlift-input");
  EXPECT_EQ(d.message.rfind("/nonexistent/tierlift-input: cannot read: ", 0), 0u) << d.message;
}
