// PNG encoding with libpng (stb_image_write cannot write 16-bit). libpng reports errors by
// longjmp, so the libpng calls live in one function whose locals are all trivially
// destructible; the C++ containers are owned by the caller.
#include <png.h>

#include <cmath>
#include <csetjmp>

#include "tierlift/image/io.h"

namespace tierlift::img {

namespace {

struct Sink {
  std::vector<uint8_t>* out;
  bool failed;
};

extern "C" void png_sink_write(png_structp png, png_bytep data, png_size_t n) {
  auto* sink = static_cast<Sink*>(png_get_io_ptr(png));
  try {
    sink->out->insert(sink->out->end(), data, data + n);
  } catch (...) {
    sink->failed = true; // out of memory: reported after libpng returns
  }
}
extern "C" void png_sink_flush(png_structp) {}
extern "C" void png_quiet_warning(png_structp, png_const_charp) {}

// rows: height pointers to packed RGBA samples (8 or 16 bit, big-endian for 16).
bool run_libpng(Sink* sink, png_bytepp rows, uint32_t width, uint32_t height, int depth) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, png_quiet_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, sink, png_sink_write, png_sink_flush);
  png_set_IHDR(png, info, width, height, depth, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 6);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// Clamp to [0, 1] (NaN → 0) and round to nearest of `steps`.
uint32_t to_unorm(float v, double steps) {
  if (std::isnan(v)) return 0;
  double c = std::fmin(std::fmax(static_cast<double>(v), 0.0), 1.0);
  return static_cast<uint32_t>(std::floor(c * steps + 0.5));
}

} // namespace

std::vector<uint8_t> encode_png(const Image& image, PngDepth depth) {
  if (image.width == 0 || image.height == 0 || image.width > kMaxDimension ||
      image.height > kMaxDimension || image.rgba.size() != size_t{image.width} * image.height * 4)
    return {};
  const bool wide = depth == PngDepth::Bits16;
  const size_t row_bytes = size_t{image.width} * 4 * (wide ? 2 : 1);
  std::vector<uint8_t> pixels(row_bytes * image.height);
  for (size_t i = 0; i < image.rgba.size(); ++i) {
    if (wide) {
      uint32_t v = to_unorm(image.rgba[i], 65535.0);
      pixels[2 * i] = static_cast<uint8_t>(v >> 8);
      pixels[2 * i + 1] = static_cast<uint8_t>(v & 0xFF);
    } else {
      pixels[i] = static_cast<uint8_t>(to_unorm(image.rgba[i], 255.0));
    }
  }
  std::vector<png_bytep> rows(image.height);
  for (uint32_t y = 0; y < image.height; ++y) rows[y] = pixels.data() + row_bytes * y;
  std::vector<uint8_t> out;
  Sink sink{&out, false};
  if (!run_libpng(&sink, rows.data(), image.width, image.height, wide ? 16 : 8) || sink.failed)
    return {};
  return out;
}

} // namespace tierlift::img
