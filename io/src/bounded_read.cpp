#include "tierlift/io/bounded_read.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

namespace tierlift::io {
namespace {

constexpr size_t kChunk = size_t{1} << 16;

std::string too_large(const std::string& path, const ReadCap& cap) {
  return fmt::format("{}: too large for a {}: the cap is {} ({} bytes)", path, cap.kind,
                     format_size(cap.bytes), cap.bytes);
}

// Closes the descriptor unless it is standard input.
struct Fd {
  int fd = -1;
  bool owned = false;
  ~Fd() {
    if (owned && fd >= 0) ::close(fd);
  }
};

} // namespace

std::string format_size(uint64_t bytes) {
  if (bytes >= (uint64_t{1} << 30) && bytes % (uint64_t{1} << 30) == 0)
    return fmt::format("{} GiB", bytes >> 30);
  if (bytes >= (uint64_t{1} << 20) && bytes % (uint64_t{1} << 20) == 0)
    return fmt::format("{} MiB", bytes >> 20);
  if (bytes >= (uint64_t{1} << 10) && bytes % (uint64_t{1} << 10) == 0)
    return fmt::format("{} KiB", bytes >> 10);
  return fmt::format("{} bytes", bytes);
}

namespace {

// The read, or nullopt with `error` set (and `rule`, when it is not "io"); read_bounded turns
// the error into a diagnostic.
std::optional<std::string> read_or_explain(const std::string& path, const ReadCap& cap,
                                           std::string& error, std::string& rule,
                                           const PrefixCheck& prefix_check) {
  const std::string name = path == "-" ? std::string("<stdin>") : path;
  Fd in;
  if (path == "-") {
    in.fd = STDIN_FILENO;
  } else {
    in.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    in.owned = true;
    if (in.fd < 0) {
      error = fmt::format("{}: cannot read: {}", name, std::strerror(errno));
      return std::nullopt;
    }
  }
  struct stat st {};
  if (::fstat(in.fd, &st) != 0) {
    error = fmt::format("{}: cannot read: {}", name, std::strerror(errno));
    return std::nullopt;
  }
  if (S_ISDIR(st.st_mode)) {
    error = fmt::format("{}: cannot read: it is a directory", name);
    return std::nullopt;
  }
  // A regular file tells its size: refuse before reading a byte of it.
  if (S_ISREG(st.st_mode) && static_cast<uint64_t>(st.st_size) > cap.bytes) {
    error = too_large(name, cap);
    return std::nullopt;
  }
  std::string data;
  if (S_ISREG(st.st_mode)) data.reserve(static_cast<size_t>(st.st_size));
  bool checked_prefix = !prefix_check;
  // Pipes, devices and files that grow while read: at most cap + 1 bytes, the extra byte
  // telling "over the cap" from "exactly the cap".
  for (;;) {
    const uint64_t room = cap.bytes + 1 - data.size();
    const size_t want = room < kChunk ? static_cast<size_t>(room) : kChunk;
    const size_t old = data.size();
    data.resize(old + want);
    ssize_t n = ::read(in.fd, data.data() + old, want);
    if (n < 0) {
      data.resize(old);
      if (errno == EINTR) continue;
      error = fmt::format("{}: read error: {}", name, std::strerror(errno));
      return std::nullopt;
    }
    data.resize(old + static_cast<size_t>(n));
    if (!checked_prefix && (n == 0 || data.size() >= kChunk)) {
      checked_prefix = true;
      if (ir::Status fits = prefix_check(data); !fits) {
        error = fmt::format("{}: {}", name, fits.message());
        for (const ir::Diagnostic& d : fits.diagnostics())
          if (d.severity == ir::Severity::Error) {
            rule = d.rule;
            break;
          }
        return std::nullopt;
      }
    }
    if (n == 0) break;
    if (data.size() > cap.bytes) {
      error = too_large(name, cap);
      return std::nullopt;
    }
  }
  return data;
}

} // namespace

ir::Result<std::string> read_bounded(const std::string& path, const ReadCap& cap,
                                     const PrefixCheck& prefix_check) {
  std::string error, rule = "io";
  std::optional<std::string> data = read_or_explain(path, cap, error, rule, prefix_check);
  if (!data)
    return ir::fail(path == "-" ? std::string("<stdin>") : path, std::move(rule), std::move(error));
  return std::move(*data);
}

} // namespace tierlift::io
