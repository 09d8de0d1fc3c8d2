// Feeds arbitrary bytes to the PNG reader. Any crash, hang or sanitizer report is a finding,
// and so is a broken invariant: a rejection carries a message; an accepted image has a
// size within the limits and as many floats as pixels × 4, and survives encode → decode
// unchanged (8-bit files hold k/255, the others k/65535, both exact at their depth) when
// it is small.
#include <cstdint>
#include <cstdlib>
#include <span>

#include "image_invariants.h"
#include "tierlift/image/io.h"

using namespace tierlift;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const img::ImageResult r = img::decode_png(std::span<const uint8_t>(data, size));
  const img::Image* checked = fuzz::checked_image(r);
  if (!checked) return 0;
  const img::Image& im = *checked;
  // The round trip (zlib both ways) costs seconds on a seed like the 1280×720 docs images
  // under the fuzzer's instrumentation; small images keep the runs fast and hold the
  // interesting shapes (palette, grey, 16-bit, odd sizes) just as well.
  if (size_t{im.width} * im.height > 65536) return 0;
  const img::PngDepth depth =
      im.format == img::Format::RGBA8 ? img::PngDepth::Bits8 : img::PngDepth::Bits16;
  img::ImageResult again = img::decode_png(img::encode_png(im, depth));
  if (!again || again->rgba != im.rgba) std::abort();
  return 0;
}
