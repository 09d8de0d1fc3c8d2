// Whole-file reads, atomic writes, and format dispatch by content or extension.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>

#include "tierlift/image/io.h"

namespace tierlift::img {

namespace {
// Larger than any valid image file we accept (16384² RGBA 16-bit PNG, stored, or PFM RGB
// plus headroom), so a runaway read cannot exhaust memory.
constexpr uint64_t kMaxFileBytes = uint64_t{16384} * 16384 * 8 + (uint64_t{1} << 24);

std::string errno_text(int err) {
  return std::strerror(err);
}
} // namespace

std::optional<std::vector<uint8_t>> read_file_bytes(const std::string& path, std::string& error) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    error = fmt::format("{}: cannot open: {}", path, errno_text(errno));
    return std::nullopt;
  }
  std::vector<uint8_t> bytes;
  uint8_t buffer[65536];
  for (;;) {
    size_t n = std::fread(buffer, 1, sizeof buffer, f);
    bytes.insert(bytes.end(), buffer, buffer + n);
    if (bytes.size() > kMaxFileBytes) {
      std::fclose(f);
      error = fmt::format("{}: file too large (over {} bytes)", path, kMaxFileBytes);
      return std::nullopt;
    }
    if (n < sizeof buffer) break;
  }
  bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) {
    error = fmt::format("{}: read error", path);
    return std::nullopt;
  }
  return bytes;
}

Status write_file_atomic(const std::string& path, std::span<const uint8_t> bytes) {
  namespace fs = std::filesystem;
  fs::path target(path);
  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  // Hidden temp file beside the target: rename() is atomic only within one file system.
  std::string tmpl = (dir / ("." + target.filename().string() + ".tmpXXXXXX")).string();
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');
  int fd = ::mkstemp(name.data());
  if (fd < 0) return {fmt::format("{}: cannot create temporary file: {}", path, errno_text(errno))};
  auto fail = [&](std::string what) {
    int err = errno;
    ::close(fd);
    ::unlink(name.data());
    return Status{fmt::format("{}: {}: {}", path, what, errno_text(err))};
  };
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return fail("write failed");
    }
    done += static_cast<size_t>(n);
  }
  // mkstemp creates 0600; images are ordinary output files.
  if (::fchmod(fd, 0644) != 0) return fail("cannot set permissions");
  if (::fsync(fd) != 0) return fail("fsync failed");
  if (::close(fd) != 0) {
    int err = errno;
    ::unlink(name.data());
    return {fmt::format("{}: close failed: {}", path, errno_text(err))};
  }
  if (std::rename(name.data(), path.c_str()) != 0) {
    int err = errno;
    ::unlink(name.data());
    return {fmt::format("{}: cannot rename temporary file into place: {}", path, errno_text(err))};
  }
  return {};
}

LoadResult read_png(const std::string& path) {
  std::string error;
  auto bytes = read_file_bytes(path, error);
  if (!bytes) return {std::nullopt, error};
  LoadResult r = decode_png(*bytes);
  if (!r) r.error = path + ": " + r.error;
  return r;
}

LoadResult read_pfm(const std::string& path) {
  std::string error;
  auto bytes = read_file_bytes(path, error);
  if (!bytes) return {std::nullopt, error};
  LoadResult r = decode_pfm(*bytes);
  if (!r) r.error = path + ": " + r.error;
  return r;
}

LoadResult read_image(const std::string& path) {
  std::string error;
  auto bytes = read_file_bytes(path, error);
  if (!bytes) return {std::nullopt, error};
  LoadResult r;
  if (bytes->size() >= 2 && (*bytes)[0] == 'P' && ((*bytes)[1] == 'F' || (*bytes)[1] == 'f')) {
    r = decode_pfm(*bytes);
  } else if (bytes->size() >= 1 && (*bytes)[0] == 0x89) {
    r = decode_png(*bytes);
  } else {
    r.error = "not a PNG or PFM file (unknown signature)";
  }
  if (!r) r.error = path + ": " + r.error;
  return r;
}

Status write_png(const std::string& path, const Image& image, PngDepth depth) {
  std::vector<uint8_t> bytes = encode_png(image, depth);
  if (bytes.empty()) return {path + ": cannot encode PNG (empty image or encoder error)"};
  return write_file_atomic(path, bytes);
}

Status write_pfm(const std::string& path, const Image& image, PfmChannels channels) {
  std::vector<uint8_t> bytes = encode_pfm(image, channels);
  if (bytes.empty()) return {path + ": cannot encode PFM (empty image)"};
  return write_file_atomic(path, bytes);
}

Status write_image(const std::string& path, const Image& image) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".pfm") return write_pfm(path, image);
  return write_png(path, image);
}

} // namespace tierlift::img
