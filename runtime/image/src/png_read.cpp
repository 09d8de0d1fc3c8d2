// PNG decoding. The chunk structure, every CRC and the IHDR fields are checked here first
// (stb_image skips CRCs, so a flipped bit would otherwise decode into a wrong picture);
// the pixels are then decoded by stb_image, compiled static into this file only.
#include <array>
#include <climits>
#include <cstring>
#include <fmt/format.h>
#include <new>

#include "tierlift/image/io.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_MAX_DIMENSIONS 16384
#include <stb/stb_image.h>

namespace tierlift::img {

static_assert(STBI_MAX_DIMENSIONS == kMaxDimension);

namespace {

constexpr std::array<uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

uint32_t be32(const uint8_t* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | p[3];
}

uint32_t crc32_update(uint32_t crc, const uint8_t* data, size_t n) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  for (size_t i = 0; i < n; ++i) crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return crc;
}

struct Header {
  uint32_t width = 0, height = 0;
  uint8_t bit_depth = 0, colour_type = 0;
};

bool valid_depth(uint8_t colour, uint8_t depth) {
  switch (colour) {
  case 0: return depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16;
  case 3: return depth == 1 || depth == 2 || depth == 4 || depth == 8;
  case 2:
  case 4:
  case 6: return depth == 8 || depth == 16;
  default: return false;
  }
}

// Walks every chunk; returns "" when the file is structurally sound.
std::string check_structure(std::span<const uint8_t> b, Header& h) {
  if (b.size() < 8 || std::memcmp(b.data(), kSignature.data(), 8) != 0)
    return "not a PNG file (bad signature)";
  size_t pos = 8;
  bool seen_ihdr = false, seen_idat = false, seen_plte = false, seen_iend = false;
  while (pos < b.size()) {
    if (seen_iend) return fmt::format("data after IEND at byte {}", pos);
    if (b.size() - pos < 12) return fmt::format("truncated chunk header at byte {}", pos);
    uint32_t len = be32(&b[pos]);
    if (len > 0x7FFFFFFFu) return fmt::format("chunk length {} out of range at byte {}", len, pos);
    if (b.size() - pos - 12 < len) return fmt::format("truncated chunk at byte {}", pos);
    const uint8_t* type = &b[pos + 4];
    for (int i = 0; i < 4; ++i) {
      bool letter = (type[i] >= 'A' && type[i] <= 'Z') || (type[i] >= 'a' && type[i] <= 'z');
      if (!letter) return fmt::format("invalid chunk type at byte {}", pos + 4);
    }
    uint32_t crc = crc32_update(0xFFFFFFFFu, type, size_t{4} + len) ^ 0xFFFFFFFFu;
    if (crc != be32(&b[pos + 8 + len]))
      return fmt::format("CRC mismatch in chunk '{}' at byte {}",
                         std::string(reinterpret_cast<const char*>(type), 4), pos);
    std::string_view name(reinterpret_cast<const char*>(type), 4);
    const uint8_t* data = &b[pos + 8];
    if (!seen_ihdr && name != "IHDR") return "first chunk is not IHDR";
    if (name == "IHDR") {
      if (seen_ihdr) return "second IHDR chunk";
      if (len != 13) return "IHDR chunk has the wrong length";
      seen_ihdr = true;
      h.width = be32(data);
      h.height = be32(data + 4);
      h.bit_depth = data[8];
      h.colour_type = data[9];
      if (h.width == 0 || h.height == 0) return "image has zero width or height";
      if (h.width > kMaxDimension || h.height > kMaxDimension)
        return fmt::format("image {}x{} exceeds the limit of {} per side", h.width, h.height,
                           kMaxDimension);
      if (!valid_depth(h.colour_type, h.bit_depth))
        return fmt::format("invalid colour type {} / bit depth {}", h.colour_type, h.bit_depth);
      if (data[10] != 0 || data[11] != 0 || data[12] > 1)
        return "unknown compression, filter or interlace method";
    } else if (name == "PLTE") {
      seen_plte = true;
    } else if (name == "IDAT") {
      seen_idat = true;
    } else if (name == "IEND") {
      seen_iend = true;
    } else if (!(type[0] & 0x20)) {
      return fmt::format("unknown critical chunk '{}'", name);
    }
    pos += size_t{12} + len;
  }
  if (!seen_iend) return "truncated file (no IEND chunk)";
  if (!seen_idat) return "no image data (IDAT)";
  if (h.colour_type == 3 && !seen_plte) return "palette image without PLTE chunk";
  return "";
}

} // namespace

ImageResult decode_png(std::span<const uint8_t> bytes) {
  auto fail = [](std::string msg) -> ImageResult {
    return ir::fail("", std::string(kImageRule), std::move(msg));
  };
  Header h;
  if (std::string err = check_structure(bytes, h); !err.empty()) return fail(err);
  if (bytes.size() > static_cast<size_t>(INT_MAX)) return fail("file too large");
  // Before inflating: the float image we would build (16 bytes a pixel; stb's own buffer
  // is a quarter or half of that on top) must fit the budget.
  const uint64_t need = uint64_t{h.width} * h.height * 4 * sizeof(float);
  if (need > kDecodeBudgetBytes)
    return fail(fmt::format("image {}x{} needs {} MiB as RGBA floats, over the decode budget of {} "
                            "MiB",
                            h.width, h.height, need >> 20, kDecodeBudgetBytes >> 20));
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  int len = static_cast<int>(bytes.size());
  int w = 0, hgt = 0, comp = 0;
  // stb checks the pixel data against IHDR before we allocate floats for it, so a small
  // file claiming a huge size costs no memory of ours.
  const bool wide = h.bit_depth == 16;
  void* px = wide ? static_cast<void*>(stbi_load_16_from_memory(data, len, &w, &hgt, &comp, 4))
                  : static_cast<void*>(stbi_load_from_memory(data, len, &w, &hgt, &comp, 4));
  if (!px) return fail(fmt::format("corrupt image data ({})", stbi_failure_reason()));
  if (static_cast<uint32_t>(w) != h.width || static_cast<uint32_t>(hgt) != h.height) {
    stbi_image_free(px);
    return fail("decoder size disagrees with IHDR");
  }
  std::optional<Image> image;
  try {
    image.emplace(h.width, h.height, wide ? Format::RGBA32F : Format::RGBA8);
  } catch (const std::bad_alloc&) {
    stbi_image_free(px);
    return fail(fmt::format("out of memory for a {}x{} image", h.width, h.height));
  }
  std::vector<float>& out = image->rgba;
  if (wide) {
    const auto* p16 = static_cast<const stbi_us*>(px);
    for (size_t i = 0; i < out.size(); ++i) out[i] = static_cast<float>(p16[i] / 65535.0);
  } else {
    // k/255 exactly as the RGBA8 store rule makes it, so read images compare exactly.
    const auto* p8 = static_cast<const stbi_uc*>(px);
    for (size_t i = 0; i < out.size(); ++i) out[i] = static_cast<float>(p8[i] / 255.0);
  }
  stbi_image_free(px);
  return ImageResult(std::move(*image));
}

} // namespace tierlift::img
