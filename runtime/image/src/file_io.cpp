// Whole-file reads (within the image cap), safe writes (tierlift::io), and format dispatch
// by content.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fmt/format.h>

#include "tierlift/image/io.h"
#include "tierlift/io/bounded_read.h"
#include "tierlift/io/output_file.h"

namespace tierlift::img {

namespace {

// Refuses, from its first bytes, a file that is neither PNG nor PFM, before more of it
// is read (a device or a pipe of noise is then refused at once).
std::string image_signature(std::string_view first) {
  static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  const bool png = first.size() >= 8 && std::memcmp(first.data(), kPng, 8) == 0;
  const bool pfm = first.size() >= 2 && first[0] == 'P' && (first[1] == 'F' || first[1] == 'f');
  return png || pfm ? "" : "not a PNG or PFM file (unknown signature)";
}

// The file, read within the image cap; io_error set when it cannot be read at all.
LoadResult read_image_file(const std::string& path, std::string& bytes) {
  std::string error;
  std::optional<std::string> read =
      io::read_bounded(path, io::kImageFileCap, error, image_signature);
  if (!read) {
    LoadResult r{std::nullopt, error};
    // A file that is there but not an image is invalid input, not an I/O error.
    r.io_error = error.find("unknown signature") == std::string::npos;
    return r;
  }
  bytes = std::move(*read);
  return {};
}

std::span<const uint8_t> as_bytes(const std::string& s) {
  return {reinterpret_cast<const uint8_t*>(s.data()), s.size()};
}

} // namespace

std::optional<std::vector<uint8_t>> read_file_bytes(const std::string& path, std::string& error) {
  std::optional<std::string> read = io::read_bounded(path, io::kImageFileCap, error);
  if (!read) return std::nullopt;
  return std::vector<uint8_t>(read->begin(), read->end());
}

Status write_file_atomic(const std::string& path, std::span<const uint8_t> bytes) {
  return {io::write_output(
      path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()))};
}

LoadResult read_png(const std::string& path) {
  std::string bytes;
  if (LoadResult r = read_image_file(path, bytes); !r.error.empty()) return r;
  LoadResult r = decode_png(as_bytes(bytes));
  if (!r) r.error = path + ": " + r.error;
  return r;
}

LoadResult read_pfm(const std::string& path) {
  std::string bytes;
  if (LoadResult r = read_image_file(path, bytes); !r.error.empty()) return r;
  LoadResult r = decode_pfm(as_bytes(bytes));
  if (!r) r.error = path + ": " + r.error;
  return r;
}

LoadResult read_image(const std::string& path) {
  std::string bytes;
  if (LoadResult r = read_image_file(path, bytes); !r.error.empty()) return r;
  LoadResult r = bytes[0] == 'P' ? decode_pfm(as_bytes(bytes)) : decode_png(as_bytes(bytes));
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

} // namespace tierlift::img
