// The address-space check before a CPU Vulkan device is created (address_space.h).
#include "address_space.h"

#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <sys/resource.h>
#include <unistd.h>

namespace tierlift::vulkan {
namespace {

constexpr uint64_t kMiB = 1ull << 20;

// Measured on Mesa 22.3 lavapipe, x86-64, with a probe that creates an instance and then a
// device and reads /proc/self/statm around vkCreateDevice: unconstrained, the device adds
// 151 MiB of address space with LP_NUM_THREADS=0, 298 MiB with 1 rasteriser thread, 446 MiB
// with 2 (the default on 2 cores), 610 MiB with 4: about 150 MiB at the base (LLVM, the
// driver) and up to 150 MiB per thread (its stack, a malloc arena of 64 MiB, its JIT
// memory). Under a limit between those figures it sometimes copes and sometimes segfaults
// (2 cores: crashes with 40, 50, 153, 162 and 289 MiB free, none from 300 MiB on), so the
// check asks for the unconstrained figure.
constexpr uint64_t kBaseBytes = 150 * kMiB;
constexpr uint64_t kPerThreadBytes = 150 * kMiB;

uint64_t mapped_bytes() {
  std::ifstream statm("/proc/self/statm");
  uint64_t pages = 0;
  if (!(statm >> pages)) return 0;
  return pages * static_cast<uint64_t>(sysconf(_SC_PAGESIZE));
}

std::string mib(uint64_t bytes) {
  return fmt::format("{} MiB", bytes / kMiB);
}

// lavapipe's rasteriser threads: LP_NUM_THREADS when set, else one per online core.
uint64_t rasteriser_threads() {
  if (const char* env = std::getenv("LP_NUM_THREADS")) {
    char* end = nullptr;
    const unsigned long n = std::strtoul(env, &end, 10);
    if (end != env && *end == '\0') return n;
  }
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  return static_cast<uint64_t>(cores > 0 ? cores : 1);
}

} // namespace

uint64_t cpu_device_address_space() {
  return kBaseBytes + rasteriser_threads() * kPerThreadBytes;
}

std::string address_space_refusal(uint64_t need) {
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) != 0 || as.rlim_cur == RLIM_INFINITY) return {};
  const uint64_t limit = as.rlim_cur, used = mapped_bytes();
  const uint64_t left = limit > used ? limit - used : 0;
  if (left >= need) return {};
  return fmt::format("the address-space limit (ulimit -v {}) leaves {} free and the Vulkan "
                     "driver needs about {} to create its device: raise the limit, or run "
                     "without Vulkan (--backend cpu)",
                     limit / 1024, mib(left), mib(need));
}

} // namespace tierlift::vulkan
