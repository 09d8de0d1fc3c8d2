// Shared by the glow benchmarks (bench_glow.cpp, glow_scaling.cpp, and any other device's
// file in bench/): the plan, the scene, and a device's steady-state frame loop.
//
// What one frame is on a tierlift device: every pass of the plan, then PassDevice::finish()
// (the work is done; nothing is read back). The graph's textures, its pipelines and the
// scene's upload are setup: begin_run, once, outside the timed loop, and so is one warm-up
// frame (the first frame also pays for first touches of pages, worker threads starting and
// pipelines made on first use: the steady state is what is measured). The GLSL peer's frame
// is the same (glsl_glow_peer.h).
#pragma once

#include <benchmark/benchmark.h>

#include <functional>
#include <memory>
#include <string>

#include "tierlift/effects/glow/glow.h"
#include "tierlift/effects/graph/device.h"
#include "tierlift/image/image.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::bench {

// The glow plan for a scene of width × height (downsample 4; taps: 0 = the default
// profile's 13, else the profile cut to that many).
effects::PlanResult glow_plan(effects::Tier tier, img::Format format, uint32_t width,
                              uint32_t height, unsigned taps = 0);
// The built-in scene at that size, RGBA32F (made once per size).
const img::Image& glow_scene(uint32_t width, uint32_t height);

// begin_run with the scene stored in the plan's format, then the timed loop of frames.
// `final_frame` (optional) receives the final texture after the loop. Skips the benchmark
// with the device's error on failure (returns false).
bool run_device_frames(benchmark::State& state, effects::PassDevice& device,
                       const effects::PlanResult& plan, const img::Image& scene,
                       img::Image* final_frame = nullptr);

// The process's Vulkan device (lavapipe, no validation), made once; nullptr and *error
// when there is none.
vulkan::Device* bench_vulkan_device(std::string* error);

// Registers BM_GlowScale_<name>/<w>x<h>/taps:<n>: the dx9 RGBA32F glow at 480×270,
// 1920×1080 and 3840×2160 with 7 and 13 taps per axis, frames on the device `make` returns
// (nullptr: skipped, e.g. no Vulkan). bench/run.sh fits time against pixels × taps for
// every name it finds. `iterations` 0: Google Benchmark decides.
using DeviceFactory = std::function<std::unique_ptr<effects::PassDevice>(std::string* error)>;
void register_glow_scaling(const std::string& name, DeviceFactory make, int iterations = 0);

} // namespace tierlift::bench
