// The listings compiled into tierlift: the article's Listings 1–4 and our own helper
// listings, addressed by their path under listings/ (e.g.
// "gpugems21/listing2_blur8_weighted_sum.psh").
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace tierlift::listings {

struct EmbeddedListing {
  std::string_view path; // relative to listings/
  std::string_view text; // the file's bytes, verbatim
};

std::span<const EmbeddedListing> embedded_listings();
std::optional<std::string_view> find_embedded(std::string_view path);

} // namespace tierlift::listings
