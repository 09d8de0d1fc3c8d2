// The listings compiled into tierlift (listings/), parsed and validated for a pass.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tierlift/ir/profile.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"

namespace tierlift::effects {

// How the glow's listings are read (the listing flags of `tierlift glow`, as `run` has them):
// applied to the built-in listings and to those a scene names.
struct ListingOptions {
  std::vector<std::pair<std::string, std::string>> defines; // -D NAME[=VALUE], in order
  std::vector<std::string> include_dirs;                    // -I DIR (files only: the
                                                            // built-in text never includes)
  // --profile: the listings of this profile's stage are validated against it instead of
  // their version line (a pass has a vertex and a pixel listing; one profile names one
  // stage, so the other stage keeps its own).
  std::optional<ir::Profile> profile;
  bool skip_validation = false; // fxc /Vd: a listing that parses is enough
  bool strict = false;          // --strict: the documented rules only, no Windows leniency
};

// "gpugems21/listing2_blur8_weighted_sum.psh", "glow/downsample4.psh", …: the parsed and
// validated program, or one error (rule "listing") whose message is the rendered diagnostics
// (or "no such listing").
using ListingResult = ir::Result<std::shared_ptr<const ir::Program>>;
ListingResult builtin_listing(std::string_view path, const ListingOptions& options = {});

// The listing a glow pass uses: `files`' entry for `path` when there is one (read from
// disk, parsed and validated; errors carry file:line:col and the caret), else the built-in.
ListingResult glow_listing(std::string_view path,
                           const std::map<std::string, std::string, std::less<>>& files,
                           const ListingOptions& options = {});

} // namespace tierlift::effects
