// The image files `tierlift run` writes and reads: -o and --output1..3 with their Vulkan
// twins, checked against the run's inputs before anything is drawn.
#pragma once

#include <string>
#include <vector>

#include "report.h"
#include "run_request.h"
#include "tierlift/pass/setup.h"

namespace tierlift::cli {

// --backend both writes the Vulkan image beside the CPU one: out.png → out-vulkan.png.
std::string vulkan_output(const std::string& output);

// The files the run reads (listings, textures, --depth-in), which no output may replace.
std::vector<std::string> input_files(const RunFlags& f, const pass::RunRequest& r);

// Every image file the run writes, in order: -o (oC0), --output1..3 (oC1..oC3) and
// --depth-out, each followed by its Vulkan twin when both devices run (`both`).
std::vector<std::string> output_files(const RunFlags& f, bool both);

// -o, --output1..3 and --depth-out (a .pfm): never one of the run's inputs nor one another,
// one image for "-" (-o only), the Vulkan images' names free too. False after reporting why
// not.
bool outputs_ok(const RunFlags& f, const pass::RunRequest& req, bool both, Report& report);

} // namespace tierlift::cli
