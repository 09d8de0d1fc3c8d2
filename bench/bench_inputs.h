// Inputs the benchmarks share: every listing we hold, read once.
#pragma once

#include <string>
#include <vector>

namespace tierlift::bench {

struct ListingText {
  std::string name, text;
};
// listings/**/*.vsh|*.psh and the shared corpus (TIERLIFT_SHARED_DIR/corpus, when present).
const std::vector<ListingText>& all_listings();
size_t total_bytes(const std::vector<ListingText>& listings);

} // namespace tierlift::bench
