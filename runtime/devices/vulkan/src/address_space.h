// Internal: whether the process's address-space limit (RLIMIT_AS, `ulimit -v`) leaves room
// for a CPU Vulkan driver to create its device. lavapipe reserves address space for LLVM and
// for a rasteriser thread per core while vkCreateDevice runs, and under a tight limit it
// crashes there (SIGSEGV) rather than returning an error; refusing first says why in words.
#pragma once

#include <cstdint>
#include <string>

namespace tierlift::vulkan {

// The address space a CPU device (lavapipe) needs free to create its device on this machine:
// a base for LLVM and the driver plus a share per rasteriser thread (one per online core, or
// LP_NUM_THREADS), as measured (address_space.cpp).
uint64_t cpu_device_address_space();

// Empty when there is no limit or it leaves `need` bytes beside what the process maps now
// (/proc/self/statm); otherwise the sentence that refuses device creation.
std::string address_space_refusal(uint64_t need);

} // namespace tierlift::vulkan
