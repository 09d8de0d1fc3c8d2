// Internal: one VkPipelineCache per device, kept across runs in the user's cache directory
// ($XDG_CACHE_HOME/tierlift, else $HOME/.cache/tierlift; TIERLIFT_PIPELINE_CACHE=off: in
// memory only), in a file named after the driver's pipelineCacheUUID, so a pipeline a
// driver compiled once need not be compiled again by the next run. The driver checks the
// data's header itself and ignores what is not its own. (lavapipe in Mesa 22.3 stores no
// pipelines in it; drivers of real GPUs do.)
#pragma once

#include "vk_internal.h"

namespace tierlift::vulkan {

// The device's cache, created (from the file, when there is one) on first use;
// VK_NULL_HANDLE when it cannot be made (pipelines are then made without one).
VkPipelineCache pipeline_cache(Device::Impl& d);
// Writes the cache's data to its file (a temporary name, then renamed into place) when
// pipelines were added since the last save. Failures are ignored: the cache only saves time.
void save_pipeline_cache(Device::Impl& d);

} // namespace tierlift::vulkan
