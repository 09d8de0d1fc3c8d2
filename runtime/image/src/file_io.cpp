// Whole-file reads (within the image cap), safe writes (tierlift::io), and format dispatch
// by content.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fmt/format.h>

#include "tierlift/image/io.h"
#include "tierlift/io/bounded_read.h"
#include "tierlift/io/output_file.h"
#include "tierlift/ir/result_diagnostics.h"

namespace tierlift::img {

namespace {

// Refuses, from its first bytes, a file that is neither PNG nor PFM, before more of it
// is read (a device or a pipe of noise is then refused at once).
ir::Status image_signature(std::string_view first) {
  static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  const bool png = first.size() >= 8 && std::memcmp(first.data(), kPng, 8) == 0;
  const bool pfm = first.size() >= 2 && first[0] == 'P' && (first[1] == 'F' || first[1] == 'f');
  if (png || pfm) return ir::ok_status();
  return ir::fail("", std::string(kImageRule), "not a PNG or PFM file (unknown signature)");
}

// The file, read within the image cap; rule kIoRule when it cannot be read at all.
ir::Result<std::string> read_image_file(const std::string& path) {
  // A file that is there but not an image fails with kImageRule (invalid input), one that
  // cannot be read with "io" (kIoRule): read_bounded keeps the check's rule.
  return io::read_bounded(path, io::kImageFileCap, image_signature);
}

// A decoder's failure with the path in front of its message. A positioned one (a PFM header
// token) becomes "PATH:LINE:COL: why" followed by the header line and a caret under the
// token, quoted from `bytes` (the header is text; the quoted line is cut at 400 bytes).
ImageResult with_path(const std::string& path, ImageResult r, const std::string& bytes) {
  if (r) return r;
  for (const ir::Diagnostic& d : r.diagnostics()) {
    if (d.severity != ir::Severity::Error || !d.loc.valid()) continue;
    ir::SourceManager sm;
    sm.add(path, bytes.substr(0, 4096));
    std::string text = ir::render_text(d, sm); // "PATH:L:C: error: why [image]\n    …\n    ^\n"
    const std::string tag = ": error: ";
    if (const size_t at = text.find(tag); at != std::string::npos)
      text.replace(at, tag.size(), ": ");
    if (const size_t rule = text.find(" [image]"); rule != std::string::npos) text.erase(rule, 8);
    while (!text.empty() && text.back() == '\n') text.pop_back();
    return ir::fail(path, std::string(kImageRule), text);
  }
  return ir::fail(path, std::string(kImageRule), path + ": " + r.message());
}

std::span<const uint8_t> as_bytes(const std::string& s) {
  return {reinterpret_cast<const uint8_t*>(s.data()), s.size()};
}

} // namespace

bool is_io_error(const ImageResult& r) {
  return ir::failed_with(r, kIoRule);
}

ir::Status write_file_atomic(const std::string& path, std::span<const uint8_t> bytes) {
  return io::write_output(
      path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

ImageResult read_png(const std::string& path) {
  ir::Result<std::string> bytes = read_image_file(path);
  if (!bytes) return std::move(bytes).failure();
  return with_path(path, decode_png(as_bytes(*bytes)), *bytes);
}

ImageResult read_pfm(const std::string& path) {
  ir::Result<std::string> bytes = read_image_file(path);
  if (!bytes) return std::move(bytes).failure();
  return with_path(path, decode_pfm(as_bytes(*bytes)), *bytes);
}

ImageResult read_image(const std::string& path) {
  ir::Result<std::string> bytes = read_image_file(path);
  if (!bytes) return std::move(bytes).failure();
  return with_path(path,
                   (*bytes)[0] == 'P' ? decode_pfm(as_bytes(*bytes)) : decode_png(as_bytes(*bytes)),
                   *bytes);
}

ir::Status write_png(const std::string& path, const Image& image, PngDepth depth) {
  std::vector<uint8_t> bytes = encode_png(image, depth);
  if (bytes.empty())
    return ir::fail(path, std::string(kWriteRule),
                    path + ": cannot encode PNG (empty image or encoder error)");
  return write_file_atomic(path, bytes);
}

ir::Status write_pfm(const std::string& path, const Image& image, PfmChannels channels) {
  std::vector<uint8_t> bytes = encode_pfm(image, channels);
  if (bytes.empty())
    return ir::fail(path, std::string(kWriteRule), path + ": cannot encode PFM (empty image)");
  return write_file_atomic(path, bytes);
}

} // namespace tierlift::img
