#include "tierlift/listings/embedded.h"

namespace tierlift::listings {

std::optional<std::string_view> find_embedded(std::string_view path) {
  for (const EmbeddedListing& l : embedded_listings())
    if (l.path == path) return l.text;
  return std::nullopt;
}

} // namespace tierlift::listings
