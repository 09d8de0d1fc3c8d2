// Where `tierlift run` writes its image.
#pragma once

#include <string>

#include "tierlift/image/image.h"

namespace tierlift::cli {

// Writes the image atomically: ".pfm" → PFM (float RGB), otherwise PNG, 8-bit for RGBA8
// targets and 16-bit for float targets. Empty string on success, else the reason. When a
// PNG must clamp values outside [0, 1] (or NaN), `warning` says so (use .pfm for HDR).
std::string write_run_output(const std::string& path, const img::Image& image,
                             std::string* warning = nullptr);

} // namespace tierlift::cli
