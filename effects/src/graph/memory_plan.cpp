// The memory planner (memory_plan.h).
#include "tierlift/effects/graph/memory_plan.h"

#include <sys/resource.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>

namespace tierlift::effects {
namespace {

constexpr uint64_t kHostBytesPerPixel = 16; // img::Image: four floats

uint64_t pixels(const TextureDesc& t) {
  return uint64_t{t.width} * t.height;
}

uint64_t stored_bytes_per_pixel(img::Format f) {
  switch (f) {
  case img::Format::RGBA8: return 4;
  case img::Format::RGBA16F: return 8;
  case img::Format::RGBA32F: return 16;
  }
  return 16;
}

uint64_t host(const TextureDesc* t) {
  return t ? pixels(*t) * kHostBytesPerPixel : 0;
}

DeviceMemory plan_device(const EffectGraph& g, const std::string& device, bool keep) {
  DeviceMemory m{device, 0, 0};
  uint64_t all_host = 0, largest = 0;
  for (const TextureDesc& t : g.textures) {
    all_host += host(&t);
    largest = std::max(largest, host(&t));
  }
  m.kept = all_host; // the run's images handed back
  if (keep)
    for (const PassDesc& p : g.passes) m.kept += host(g.find_texture(p.target));
  // The textures some pass samples, and those it samples through the Vulkan device's float
  // copy: every read of an RGBA16F texture; of an RGBA8 one, all but point reads with edge
  // clamping, which fetch the stored bytes in place (codegen::CodegenOptions::
  // stage_fetch_unorm8).
  std::set<std::string_view> sampled, copied;
  for (const PassDesc& p : g.passes)
    for (const TextureBind& b : p.textures) {
      sampled.insert(b.texture);
      if (b.stage >= pass::kMaxSamplers || !pass::point_clamped(p.draw.textures[b.stage].sampler))
        copied.insert(b.texture);
    }

  if (device == "vulkan") {
    uint64_t largest_stored = 0;
    for (const TextureDesc& t : g.textures) {
      const uint64_t stored = pixels(t) * stored_bytes_per_pixel(t.format);
      largest_stored = std::max(largest_stored, stored);
      m.kept += stored;
      if (t.format == img::Format::RGBA16F && sampled.count(t.name)) m.kept += pixels(t) * 16;
      // RGBA8: the float image (16 bytes a texel), which a device reading RGBA8 in place
      // draws; one that cannot converts it by compute through two buffers (4 + 16 bytes).
      // The plan does not know which device runs it and counts the larger.
      if (t.format == img::Format::RGBA8 && copied.count(t.name)) m.kept += pixels(t) * 36;
    }
    // A read: staging in the stored format plus the host image it becomes (before it
    // replaces the kept one); an upload: the caller's inputs copy and staging.
    m.transient = largest_stored + largest;
  } else if (device == "analytic") {
    for (const TextureDesc& t : g.textures) {
      m.kept += host(&t);
      if (t.format == img::Format::RGBA8) m.kept += pixels(t);
    }
    for (const PassDesc& p : g.passes) {
      const TextureDesc* target = g.find_texture(p.target);
      uint64_t during = host(target);
      if (target && target->format == img::Format::RGBA8)
        for (const TextureBind& b : p.textures) during += host(g.find_texture(b.texture));
      m.transient = std::max(m.transient, during);
    }
  } else { // cpu
    // Its own image of every texture. A pass draws into its target in place and binds the
    // textures it samples by reference (CpuPassDevice::draw), so a draw copies nothing; what
    // is made beside the kept images is a read's copy, before it replaces the kept one.
    for (const TextureDesc& t : g.textures) m.kept += host(&t);
    m.transient = largest;
  }
  // begin_run's copy of the inputs.
  uint64_t inputs = 0;
  for (const TextureDesc& t : g.textures)
    if (t.input) inputs += host(&t);
  m.transient = std::max(m.transient, inputs);
  return m;
}

} // namespace

MemoryPlan plan_memory(const EffectGraph& graph, const std::vector<std::string>& devices,
                       bool keep_pass_images, uint64_t extra) {
  MemoryPlan plan;
  uint64_t top = 0;
  plan.peak = extra;
  // The inputs the graph carries itself (a glow image, a fog's depth: TextureDesc::contents)
  // stay beside every run, as the scene image the caller holds does.
  for (const TextureDesc& t : graph.textures)
    if (t.contents)
      plan.peak += uint64_t{t.contents->width} * t.contents->height * 4 * sizeof(float);
  for (const std::string& d : devices) {
    plan.devices.push_back(plan_device(graph, d, keep_pass_images));
    plan.peak += plan.devices.back().kept;
    top = std::max(top, plan.devices.back().transient);
  }
  plan.peak += top;
  return plan;
}

uint64_t available_memory() {
  uint64_t available = 0;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    std::istringstream in(line);
    std::string key;
    uint64_t kib = 0;
    if (in >> key >> kib && key == "MemAvailable:") available = kib * 1024;
  }
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
    available = available ? std::min<uint64_t>(available, as.rlim_cur) : as.rlim_cur;
  if (ir::Result<std::optional<uint64_t>> limit = memory_limit_from_env(); limit && *limit)
    available = available ? std::min(available, **limit) : **limit;
  return available;
}

std::string memory_refusal(const MemoryPlan& plan, uint64_t available, const std::string& what) {
  if (available == 0 || plan.peak <= available) return {};
  return fmt::format("{} needs {} of memory at its peak and {} is available", what,
                     format_bytes(plan.peak), format_bytes(available));
}

ir::Result<std::optional<uint64_t>> memory_limit_from_env() {
  const char* limit = std::getenv("TIERLIFT_MEMORY_LIMIT");
  if (!limit) return std::optional<uint64_t>();
  uint64_t bytes = 0;
  const char* end = limit + std::strlen(limit);
  auto [ptr, ec] = std::from_chars(limit, end, bytes);
  if (ec == std::errc() && ptr == end && bytes > 0) return std::optional<uint64_t>(bytes);
  return ir::fail("TIERLIFT_MEMORY_LIMIT", "usage",
                  fmt::format("TIERLIFT_MEMORY_LIMIT='{}': expected a whole number of bytes > 0 "
                              "(e.g. 4294967296 for 4 GiB)",
                              limit));
}

std::string format_bytes(uint64_t bytes) {
  const double gib = double(bytes) / (1024.0 * 1024.0 * 1024.0);
  if (gib >= 1) return fmt::format("{:.1f} GiB ({} bytes)", gib, bytes);
  return fmt::format("{:.1f} MiB ({} bytes)", double(bytes) / (1024.0 * 1024.0), bytes);
}

} // namespace tierlift::effects
