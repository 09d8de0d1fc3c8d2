// Reading and writing images: PNG (8/16 bit) and PFM (float). Every reader validates its
// input completely (magic, chunk structure and CRCs, sizes, truncation) and turns every
// problem into a diagnostic (ir::Result); nothing throws on bad input. Writers write to a temporary
// file in the target folder and rename it into place, so no half-written file is left.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"

namespace tierlift::img {

// An image, or the diagnostic that says why there is none. Its subject is the path (or
// builtin spec) and its message starts with it too ("PATH: why"), as callers print the
// message alone. The rule says what kind of failure it is: kIoRule when the file could not
// be read at all (missing, unreadable, over the cap), kImageRule when it is there but is not
// a valid image (or a builtin spec is malformed), kWriteRule when an output cannot be written.
using ImageResult = ir::Result<Image>;
inline constexpr std::string_view kIoRule = "io";
inline constexpr std::string_view kImageRule = "image";
inline constexpr std::string_view kWriteRule = "write";
// True when `r` failed because its file could not be read (rule kIoRule).
bool is_io_error(const ImageResult& r);

// PNG of any colour type (grey, grey+alpha, RGB, RGBA, palette) at 8 or 16 bits (1/2/4-bit
// grey and palette are accepted too) → RGBA floats in [0, 1]: value / 255 or / 65535.
// Grey fills R, G and B; a missing alpha reads 1. gAMA/sRGB chunks are ignored (values
// are taken as stored). The result's format is RGBA8 for 8-bit files (values are exactly
// RGBA8 store values) and RGBA32F otherwise. IHDR's width × height is checked against
// kDecodeBudgetBytes before anything is inflated, so a small file claiming a huge image is
// refused at once.
inline constexpr uint64_t kDecodeBudgetBytes = uint64_t{1} << 30; // 1 GiB of RGBA floats
ImageResult decode_png(std::span<const uint8_t> bytes);
ImageResult read_png(const std::string& path);

// PFM: "PF" (RGB) or "Pf" (grey), width, height, scale; a negative scale means little-
// endian floats, positive big-endian. Rows are stored bottom to top; the returned image is
// top row first as always. Grey fills R, G, B; alpha reads 1. Format: RGBA32F.
ImageResult decode_pfm(std::span<const uint8_t> bytes);
ImageResult read_pfm(const std::string& path);

// By content: PNG signature or PFM magic.
ImageResult read_image(const std::string& path);

enum class PngDepth { Bits8 = 8, Bits16 = 16 };

// RGBA PNG. Each channel is clamped to [0, 1] (NaN → 0) and rounded to nearest of 255 or
// 65535 steps, so an RGBA8 image is written exactly as stored.
std::vector<uint8_t> encode_png(const Image& image, PngDepth depth = PngDepth::Bits8);
ir::Status write_png(const std::string& path, const Image& image, PngDepth depth = PngDepth::Bits8);

// PFM little-endian (scale -1). RGB ("PF") by default; grey ("Pf") writes the R channel.
// Alpha is dropped: PFM has no alpha channel (it reads back as 1).
enum class PfmChannels { RGB, Grey };
std::vector<uint8_t> encode_pfm(const Image& image, PfmChannels channels = PfmChannels::RGB);
ir::Status write_pfm(const std::string& path, const Image& image,
                     PfmChannels channels = PfmChannels::RGB);

// Writes bytes with tierlift::io::write_output: temp file in the same folder renamed over
// `path` (symbolic links followed), FIFOs and character devices written straight through.
ir::Status write_file_atomic(const std::string& path, std::span<const uint8_t> bytes);

} // namespace tierlift::img
