// Memory known before running: the bytes a run of an effect graph holds at its peak on each
// device, computed from the graph alone (texture sizes and formats, the passes' bindings),
// so a scene that cannot fit is refused before anything is allocated.
//
// The model follows what the code keeps, per texture of w × h pixels (host images are
// img::Image: four floats a pixel, whatever the format):
//   * every device: the run's copy of every texture handed back at the end (run_graph's
//     images), and with per-pass images kept (the agreement table) one image per pass;
//   * cpu: its own copy of every texture; a pass draws into its target in place and binds
//     what it samples by reference (nothing copied), so beside them only a read's copy of
//     one texture (the largest), made before it replaces the kept one, or begin_run's copy
//     of the inputs when that is larger;
//   * vulkan (lavapipe: device memory is host memory): every texture in its own format,
//     plus the float copy (16 B/px) of an RGBA16F texture that a pass samples and of an
//     RGBA8 texture that a pass samples other than by a point read with edge clamping (such
//     a read fetches the stored bytes in place), with, RGBA8, the conversion's byte and
//     float buffers (20 B/px); during a read or an upload a staging buffer in the texture's
//     format;
//   * analytic: its own copy of every texture and a midpoint mask (1 B/px) of each RGBA8
//     one, plus during a pass the new target and, RGBA8, a float slack image of each read.
// Devices run one after another and their results stay (the agreement table compares them),
// so the peak is what the earlier devices keep plus the largest transient of any.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/effects/graph/graph.h"
#include "tierlift/ir/result.h"

namespace tierlift::effects {

struct DeviceMemory {
  std::string device;     // "cpu", "vulkan", "analytic"
  uint64_t kept = 0;      // held from its run until the end
  uint64_t transient = 0; // held only while it runs (beyond `kept`)
};

struct MemoryPlan {
  std::vector<DeviceMemory> devices;
  uint64_t peak = 0; // Σ kept + max transient + the caller's extra
};

// `devices` in the order they run; `keep_pass_images`: one image per pass kept (run_graph);
// `extra`: bytes the caller holds throughout (e.g. the scene as loaded); the inputs the graph
// carries (TextureDesc::contents) are counted here beside it. Unknown device
// names count as the cpu device.
MemoryPlan plan_memory(const EffectGraph& graph, const std::vector<std::string>& devices,
                       bool keep_pass_images, uint64_t extra = 0);

// The memory this machine can give now: MemAvailable of /proc/meminfo, lowered to the
// process's address-space limit (RLIMIT_AS) when one is set, and to TIERLIFT_MEMORY_LIMIT
// (a whole number of bytes) when that is set: a budget for shared machines, and the one
// limit that works under AddressSanitizer, whose shadow memory needs an unlimited address
// space. 0 when unknown.
uint64_t available_memory();
// TIERLIFT_MEMORY_LIMIT as available_memory reads it: unset (nullopt), a whole number of
// bytes > 0, or an error (rule "usage") naming the variable and its value: a budget that
// is mistyped must not be dropped without a word.
ir::Result<std::optional<uint64_t>> memory_limit_from_env();

// Held beside the images by every run: the program, its listings and the Vulkan driver
// (lavapipe, LLVM), measured at 92 MB resident for a 16×16 glow on all three devices.
inline constexpr uint64_t kProgramBytes = 96ull << 20;

// Empty when the plan's peak fits `available` (0: unknown, nothing to hold against);
// otherwise the sentence refusing the run before anything is allocated: "<what> needs 8.0 GiB
// (…) of memory at its peak and 1.0 GiB (…) is available".
std::string memory_refusal(const MemoryPlan& plan, uint64_t available, const std::string& what);

// "1.5 GiB (1610612736 bytes)"
std::string format_bytes(uint64_t bytes);

} // namespace tierlift::effects
