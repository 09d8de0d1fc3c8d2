// tierlift run --trace X,Y: the pass's pixel listing followed at one pixel on the devices the
// run uses (effects/pixel_trace.h), printed after the run's own output or carried in its
// JSON result as "trace".
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "report.h"
#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"
#include "tierlift/pass/setup.h"

namespace tierlift::cli {

struct PixelTraceRequest {
  uint32_t x = 0, y = 0;
  uint32_t width = 0, height = 0;
  img::Format format = img::Format::RGBA32F;
  bool interpreter = true, vulkan = false; // the columns (the run's --backend)
  std::string gpu;                         // --gpu
};

// --trace X,Y checked against the run's target and listings: no request when the flag is
// empty, a usage failure when X,Y is malformed or outside the target or there is no --ps.
ir::Result<std::optional<PixelTraceRequest>> trace_request(const std::string& flag, bool has_ps,
                                                           const pass::RunRequest& run, bool cpu,
                                                           bool vulkan, const std::string& gpu);

// Traces `pass` and prints the table (text) or sets report.result()["trace"] (--json).
// Returns the exit code to finish with when the trace failed (the error already reported),
// else 0.
int print_pixel_trace(const pass::Pass& pass, const PixelTraceRequest& request, Report& report);

} // namespace tierlift::cli
