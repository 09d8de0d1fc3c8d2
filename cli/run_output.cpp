// `tierlift run -o`: PNG or PFM, with a warning when PNG clamps.
#include "run_output.h"

#include <fmt/format.h>

#include "tierlift/image/io.h"

namespace tierlift::cli {

std::string write_run_output(const std::string& path, const img::Image& image,
                             std::string* warning) {
  const bool pfm = path.size() >= 4 && (path.ends_with(".pfm") || path.ends_with(".PFM"));
  if (!pfm && warning) {
    size_t clamped = 0;
    for (float v : image.rgba) clamped += !(v >= 0.0f && v <= 1.0f);
    if (clamped)
      *warning = fmt::format("{}: {} channel values outside [0, 1] are clamped in PNG; write "
                             ".pfm to keep them",
                             path, clamped);
  }
  ir::Status s = pfm ? img::write_pfm(path, image)
                     : img::write_png(path, image,
                                      image.format == img::Format::RGBA8 ? img::PngDepth::Bits8
                                                                         : img::PngDepth::Bits16);
  return s.message();
}

} // namespace tierlift::cli
