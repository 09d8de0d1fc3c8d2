#include "tierlift/io/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "temp_registry.h"

namespace tierlift::io {
namespace {

bool write_all(int fd, std::string_view bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<size_t>(n);
  }
  return true;
}

// The file a chain of symbolic links ends at (the path itself when it is no link). A
// dangling link resolves to the missing file it names, which is then created.
std::string follow_links(const std::string& path) {
  namespace fs = std::filesystem;
  fs::path p(path);
  for (int hops = 0; hops < 40; ++hops) { // the kernel's own limit on link chains
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) break;
    std::error_code ec;
    fs::path next = fs::read_symlink(p, ec);
    if (ec) break;
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  return p.string();
}

mode_t new_file_mode(const std::string& target) {
  struct stat st {};
  if (::stat(target.c_str(), &st) == 0) return st.st_mode & 07777; // keep the old file's
  mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

} // namespace

AtomicFile::AtomicFile(const std::string& target) : target_(follow_links(target)), shown_(target) {
  namespace fs = std::filesystem;
  fs::path t(target_);
  fs::path dir = t.parent_path();
  if (dir.empty()) dir = ".";
  // Hidden, beside the target: rename() is atomic only within one file system.
  // fmt::format, not "." + name + "…": GCC 12 -O3 reports a false -Wrestrict in the inlined
  // std::string concatenation (GCC bug 105651), which fails a Release build under -Werror.
  std::string pattern = (dir / fmt::format(".{}.tmpXXXXXX", t.filename().string())).string();
  int err = 0;
  slot_ = detail::create_registered_temp(pattern, &fd_, &err);
  if (slot_ < 0) {
    fail("cannot create a temporary file beside it", err);
    return;
  }
  temp_ = detail::registered_temp_name(slot_);
  if (::fchmod(fd_, new_file_mode(target_)) != 0) fail("cannot set permissions", errno);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (slot_ >= 0) detail::remove_registered_temp(slot_, !committed_);
}

void AtomicFile::fail(const std::string& what, int err) {
  if (error_.empty()) error_ = fmt::format("{}: {}: {}", shown_, what, std::strerror(err));
}

ir::Status AtomicFile::status() const {
  if (error_.empty()) return ir::ok_status();
  return ir::fail(shown_, "write", error_);
}

ir::Status AtomicFile::write(std::string_view bytes) {
  if (error_.empty() && !write_all(fd_, bytes)) fail("write failed", errno);
  return status();
}

ir::Status AtomicFile::commit() {
  if (!error_.empty()) return status();
  if (::fsync(fd_) != 0) {
    fail("fsync failed", errno);
    return status();
  }
  int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) {
    fail("close failed", errno);
    return status();
  }
  int err = 0;
  if (!detail::rename_registered_temp(slot_, target_, &err)) {
    fail("cannot rename the temporary file into place", err);
    return status();
  }
  committed_ = true;
  return ir::ok_status();
}

namespace {

// "" on success, otherwise why the write failed; write_output makes it a diagnostic.
std::string write_or_explain(const std::string& path, std::string_view bytes) {
  if (path == "-") {
    std::fflush(stdout); // text printed before stays before
    if (!write_all(STDOUT_FILENO, bytes))
      return fmt::format("<stdout>: write failed: {}", std::strerror(errno));
    return "";
  }
  if (path.empty()) return "no output file named";
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) return fmt::format("{}: cannot write: it is a directory", path);
    if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) {
      // A pipe or device: replacing it with a regular file would break the user's setup.
      int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
      if (fd < 0) return fmt::format("{}: cannot write: {}", path, std::strerror(errno));
      bool done = write_all(fd, bytes);
      int err = errno;
      ::close(fd);
      if (!done) return fmt::format("{}: write failed: {}", path, std::strerror(err));
      return "";
    }
    if (!S_ISREG(st.st_mode))
      return fmt::format("{}: cannot write: not a regular file, FIFO or character device", path);
  }
  AtomicFile out(path);
  ir::Status written = out.write(bytes);
  if (written) written = out.commit();
  return written.message();
}

} // namespace

ir::Status write_output(const std::string& path, std::string_view bytes) {
  std::string error = write_or_explain(path, bytes);
  if (error.empty()) return ir::ok_status();
  return ir::fail(path == "-" ? std::string("<stdout>") : path, "write", std::move(error));
}

bool same_file(const std::string& a, const std::string& b) {
  if (a == "-" || b == "-" || a.empty() || b.empty()) return false;
  struct stat sa {
  }, sb{};
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

ir::Status refuse_if_input(const std::string& output, std::span<const std::string> inputs) {
  for (const std::string& in : inputs)
    if (same_file(output, in))
      return ir::fail(output, "write",
                      in == output
                          ? fmt::format("{}: refusing to write over an input file", output)
                          : fmt::format("{}: refusing to write over the input file {} (the "
                                        "same file)",
                                        output, in));
  return ir::ok_status();
}

} // namespace tierlift::io
