// Feeds arbitrary bytes to the PFM reader. Any crash, hang or sanitizer report is a finding,
// and so is a broken invariant: a rejection carries a message, an accepted image has a
// size within the limits (image_invariants.h), alpha 1, and survives encode → decode bit for bit
// (NaN payloads included: floats are copied, never computed on).
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>

#include "image_invariants.h"
#include "tierlift/image/io.h"

using namespace tierlift;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const img::ImageResult r = img::decode_pfm(std::span<const uint8_t>(data, size));
  const img::Image* checked = fuzz::checked_image(r);
  if (!checked) return 0;
  const img::Image& im = *checked;
  for (size_t i = 3; i < im.rgba.size(); i += 4)
    if (im.rgba[i] != 1.0f) std::abort();
  img::ImageResult again = img::decode_pfm(img::encode_pfm(im));
  if (!again || again->rgba.size() != im.rgba.size() ||
      std::memcmp(again->rgba.data(), im.rgba.data(), im.rgba.size() * sizeof(float)) != 0)
    std::abort();
  return 0;
}
