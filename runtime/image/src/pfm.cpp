// PFM (Portable Float Map): "PF" RGB or "Pf" grey, decimal width and height, a scale
// whose sign gives the byte order (negative = little-endian), one white-space byte, then
// 32-bit floats, rows bottom to top.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fmt/format.h>
#include <new>
#include <string>

#include "tierlift/image/io.h"

namespace tierlift::img {

namespace {

bool is_space(uint8_t c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Header fields are short; a longer run of digits is corruption, not a number.
constexpr size_t kMaxFieldChars = 32;

struct Cursor {
  std::span<const uint8_t> b;
  size_t pos = 0;
  bool skip_space() {
    size_t start = pos;
    while (pos < b.size() && is_space(b[pos])) ++pos;
    return pos > start;
  }
  std::string token() {
    std::string t;
    while (pos < b.size() && !is_space(b[pos]) && t.size() <= kMaxFieldChars)
      t.push_back(static_cast<char>(b[pos++]));
    return t;
  }
};

std::optional<uint32_t> parse_size(const std::string& t) {
  if (t.empty() || t.size() > 9) return std::nullopt;
  uint32_t v = 0;
  for (char c : t) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + static_cast<uint32_t>(c - '0');
  }
  return v;
}

} // namespace

ImageResult decode_pfm(std::span<const uint8_t> bytes) {
  auto fail = [](std::string msg) -> ImageResult {
    return ir::fail("", std::string(kImageRule), std::move(msg));
  };
  // A header error at the token it is about: line and column in the header's text (file 0:
  // the caller's; read_pfm and read_image quote the line with a caret).
  auto fail_at = [&](size_t offset, size_t length, std::string msg) -> ImageResult {
    ir::SourceLoc loc;
    loc.line = 1;
    size_t line_start = 0;
    for (size_t i = 0; i < offset && i < bytes.size(); ++i)
      if (bytes[i] == '\n') ++loc.line, line_start = i + 1;
    loc.col = static_cast<uint32_t>(offset - line_start + 1);
    loc.length = static_cast<uint32_t>(std::max<size_t>(1, length));
    return ir::fail_at(loc, std::string(kImageRule), std::move(msg));
  };
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != 'F' && bytes[1] != 'f'))
    return fail_at(0, 2, "not a PFM file (magic must be PF or Pf)");
  const uint32_t channels = bytes[1] == 'F' ? 3 : 1;
  Cursor c{bytes, 2};
  if (!c.skip_space()) return fail_at(2, 1, "PFM header: expected white space after the magic");
  const size_t w_at = c.pos;
  std::string wt = c.token();
  if (!c.skip_space()) return fail_at(c.pos, 1, "PFM header: truncated after the width");
  const size_t h_at = c.pos;
  std::string ht = c.token();
  if (!c.skip_space()) return fail_at(c.pos, 1, "PFM header: truncated after the height");
  const size_t s_at = c.pos;
  std::string st = c.token();
  auto w = parse_size(wt), h = parse_size(ht);
  if (!w) return fail_at(w_at, wt.size(), fmt::format("PFM header: bad width '{}'", wt));
  if (!h) return fail_at(h_at, ht.size(), fmt::format("PFM header: bad height '{}'", ht));
  if (*w == 0 || *h == 0)
    return fail_at(*w == 0 ? w_at : h_at, 1, "PFM header: zero width or height");
  if (*w > kMaxDimension || *h > kMaxDimension)
    return fail_at(
        *w > kMaxDimension ? w_at : h_at, (*w > kMaxDimension ? wt : ht).size(),
        fmt::format("PFM image {}x{} exceeds the limit of {} per side", *w, *h, kMaxDimension));
  // The scale: a decimal number, not zero, finite; only its sign matters to us.
  if (st.empty() || st.size() > kMaxFieldChars)
    return fail_at(s_at, st.size(), "PFM header: bad scale");
  char* end = nullptr;
  double scale = std::strtod(st.c_str(), &end);
  if (end != st.c_str() + st.size() || !std::isfinite(scale) || scale == 0.0)
    return fail_at(s_at, st.size(),
                   fmt::format("PFM header: bad scale '{}' (a finite number, not 0; negative: "
                               "little-endian)",
                               st));
  // Exactly one white-space byte separates the header from the raster.
  if (c.pos >= bytes.size() || !is_space(bytes[c.pos]))
    return fail_at(c.pos, 1, "PFM header: truncated after the scale");
  ++c.pos;
  const bool little = scale < 0;
  const uint64_t need = uint64_t{*w} * *h * channels * 4;
  const uint64_t have = bytes.size() - c.pos;
  if (have < need)
    return fail(fmt::format("PFM raster truncated: {} bytes, {} needed", have, need));
  if (have > need) return fail(fmt::format("PFM has {} bytes after the raster", have - need));
  const bool swap = little != (std::endian::native == std::endian::little);
  std::optional<Image> holder;
  try {
    holder.emplace(*w, *h, Format::RGBA32F);
  } catch (const std::bad_alloc&) {
    return fail(fmt::format("out of memory for a {}x{} image", *w, *h));
  }
  Image& image = *holder;
  const uint8_t* p = bytes.data() + c.pos;
  for (uint32_t row = 0; row < *h; ++row) {
    uint32_t y = *h - 1 - row; // stored bottom to top
    for (uint32_t x = 0; x < *w; ++x) {
      float* px = image.at(x, y);
      for (uint32_t ch = 0; ch < channels; ++ch, p += 4) {
        uint32_t raw;
        std::memcpy(&raw, p, 4);
        if (swap) raw = __builtin_bswap32(raw);
        px[ch] = std::bit_cast<float>(raw);
      }
      if (channels == 1) px[1] = px[2] = px[0];
      px[3] = 1.0f;
    }
  }
  return ImageResult(std::move(*holder));
}

std::vector<uint8_t> encode_pfm(const Image& image, PfmChannels channels) {
  if (image.width == 0 || image.height == 0 || image.width > kMaxDimension ||
      image.height > kMaxDimension || image.rgba.size() != size_t{image.width} * image.height * 4)
    return {};
  const uint32_t n = channels == PfmChannels::RGB ? 3 : 1;
  std::string header =
      fmt::format("{}\n{} {}\n-1.0\n", n == 3 ? "PF" : "Pf", image.width, image.height);
  std::vector<uint8_t> out(header.begin(), header.end());
  out.reserve(out.size() + size_t{image.width} * image.height * n * 4);
  for (uint32_t row = 0; row < image.height; ++row) {
    uint32_t y = image.height - 1 - row;
    for (uint32_t x = 0; x < image.width; ++x) {
      const float* px = image.at(x, y);
      for (uint32_t ch = 0; ch < n; ++ch) {
        uint32_t raw = std::bit_cast<uint32_t>(px[ch]);
        if constexpr (std::endian::native != std::endian::little) raw = __builtin_bswap32(raw);
        uint8_t b[4];
        std::memcpy(b, &raw, 4);
        out.insert(out.end(), b, b + 4);
      }
    }
  }
  return out;
}

} // namespace tierlift::img
