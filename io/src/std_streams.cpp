#include "tierlift/io/std_streams.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <fmt/format.h>

namespace tierlift::io {
namespace {

// errno of the first failed write to standard output that we saw (0: none seen).
int g_stdout_errno = 0;
std::string g_program = "tierlift";

void stdout_check_at_exit() {
  const std::string why = flush_stdout();
  if (why.empty()) return;
  std::fprintf(stderr, "%s: error: %s\n", g_program.c_str(), why.c_str());
  std::fflush(stderr);
  ::_exit(2);
}

} // namespace

void guard_standard_streams() {
  struct Guard {
    int fd, flags;
  };
  for (Guard g : {Guard{STDIN_FILENO, O_WRONLY}, Guard{STDOUT_FILENO, O_RDONLY},
                  Guard{STDERR_FILENO, O_RDONLY}}) {
    if (::fcntl(g.fd, F_GETFD) != -1 || errno != EBADF) continue;
    int fd = ::open("/dev/null", g.flags);
    if (fd >= 0 && fd != g.fd) {
      ::dup2(fd, g.fd);
      ::close(fd);
    }
  }
}

std::string flush_stdout() {
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  if (!flushed && g_stdout_errno == 0) g_stdout_errno = errno;
  if (flushed && !std::ferror(stdout)) return "";
  // An earlier write may have failed inside stdio (a buffer flushed by printf): the error
  // flag stays, its errno may not; a write of nothing asks the descriptor itself.
  if (g_stdout_errno == 0 && ::write(STDOUT_FILENO, "", 0) < 0) g_stdout_errno = errno;
  return fmt::format("<stdout>: write failed: {}",
                     g_stdout_errno ? std::strerror(g_stdout_errno) : "an earlier write failed");
}

void check_stdout_at_exit(const std::string& program) {
  static bool registered = false;
  g_program = program;
  if (registered) return;
  registered = true;
  std::atexit(stdout_check_at_exit);
}

} // namespace tierlift::io
