// `tierlift run`'s depth buffer: the --depth-* flags into the pass's depth state and the
// graph's depth buffer (effects::SinglePassDepth), and the depth image written out.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "run_request.h"
#include "tierlift/effects/graph/single_pass.h"
#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"

namespace tierlift::cli {

// Whether any --depth-* flag was given (the run then draws with a depth buffer).
bool wants_depth(const RunFlags& f);

// The depth state the flags ask for: ZENABLE on, ZFUNC --depth-func (default lessequal),
// ZWRITEENABLE --depth-write (default on). Fails (rule "usage") on a word it does not know or a
// --depth-clear that is not a number in [0, 1] (D3D9's Clear takes z in 0..1).
ir::Result<pass::DepthStencilState> depth_state(const RunFlags& f);

// The depth buffer's start: --depth-clear (default 1.0) everywhere, or --depth-in's red
// channel (a .pfm of the target's size whose every value lies in [0, 1]). Fails (rule "usage"
// for the values and size, "io" for an unreadable file).
ir::Result<effects::SinglePassDepth> depth_start(const RunFlags& f, uint32_t width,
                                                 uint32_t height);

// Writes a depth buffer (depth in red, as the devices return it) as a grey .pfm ("Pf": one
// float per pixel, which reads back as R = G = B = depth, so it serves as --depth-in), whole
// or not at all; empty on success, else why not.
std::string write_depth_output(const std::string& path, const img::Image& depth);

// --depth-out: the shown device's depth buffer (the CPU one when it ran), and with two
// devices the Vulkan one beside it (vulkan_output). Empty on success, else the file and why.
std::string write_depth_outputs(const RunFlags& f, const effects::SinglePassRun& r);

// With two devices, the depth buffers compared, as the oC1 line: "depth: cpu vs vulkan: max abs
// …, identical pixels … %: bit for bit". Nothing for a run without a depth buffer.
void print_depth_agreement(const effects::SinglePassRun& r);
// result.depth under --json: the state, the files and, with two devices, the agreement
// (max_abs, identical_share, bit_identical, summary); null without a depth buffer.
nlohmann::json depth_json(const RunFlags& f, const pass::DepthStencilState& ds,
                          const effects::SinglePassRun& r);

} // namespace tierlift::cli
