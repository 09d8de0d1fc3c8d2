// The invariants every image reader keeps, whatever the bytes: a rejection carries a
// message; an accepted image has a size within the limits and four floats per pixel. A
// broken one aborts, which the fuzzer reports as a finding.
#pragma once

#include <cstdlib>

#include "tierlift/image/io.h"

namespace tierlift::fuzz {

// The decoded image, or nullptr for a (well-formed) rejection.
inline const img::Image* checked_image(const img::ImageResult& r) {
  if (!r) {
    if (r.message().empty()) std::abort();
    return nullptr;
  }
  const img::Image& im = *r;
  if (im.width == 0 || im.height == 0 || im.width > img::kMaxDimension ||
      im.height > img::kMaxDimension || im.rgba.size() != size_t{im.width} * im.height * 4)
    std::abort();
  return &im;
}

} // namespace tierlift::fuzz
