// The persistent pipeline cache (pipeline_cache.h).
#include "pipeline_cache.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <fmt/format.h>

namespace tierlift::vulkan {
namespace {

namespace fs = std::filesystem;

// Empty when caching to disk is off or no directory is known.
fs::path cache_file(const Device::Impl& d) {
  const char* off = std::getenv("TIERLIFT_PIPELINE_CACHE");
  if (off && std::string(off) == "off") return {};
  fs::path dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    dir = fs::path(xdg) / "tierlift";
  else if (const char* home = std::getenv("HOME"); home && *home)
    dir = fs::path(home) / ".cache" / "tierlift";
  else
    return {};
  std::string uuid;
  for (uint8_t b : d.props.pipelineCacheUUID) uuid += fmt::format("{:02x}", b);
  return dir /
         fmt::format("pipelines-{:04x}-{:04x}-{}.bin", d.props.vendorID, d.props.deviceID, uuid);
}

} // namespace

VkPipelineCache pipeline_cache(Device::Impl& d) {
  if (d.pipeline_cache != VK_NULL_HANDLE || d.pipeline_cache_failed) return d.pipeline_cache;
  std::vector<char> data;
  if (const fs::path file = cache_file(d); !file.empty()) {
    std::ifstream in(file, std::ios::binary);
    data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  VkPipelineCacheCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO;
  ci.initialDataSize = data.size();
  ci.pInitialData = data.empty() ? nullptr : data.data();
  if (vkCreatePipelineCache(d.device, &ci, nullptr, &d.pipeline_cache) != VK_SUCCESS) {
    // Data the driver rejects outright: start empty.
    ci.initialDataSize = 0;
    ci.pInitialData = nullptr;
    if (vkCreatePipelineCache(d.device, &ci, nullptr, &d.pipeline_cache) != VK_SUCCESS) {
      d.pipeline_cache = VK_NULL_HANDLE;
      d.pipeline_cache_failed = true;
    }
  }
  return d.pipeline_cache;
}

void save_pipeline_cache(Device::Impl& d) {
  if (d.pipeline_cache == VK_NULL_HANDLE || !d.pipeline_cache_dirty) return;
  d.pipeline_cache_dirty = false;
  const fs::path file = cache_file(d);
  if (file.empty()) return;
  size_t size = 0;
  if (vkGetPipelineCacheData(d.device, d.pipeline_cache, &size, nullptr) != VK_SUCCESS) return;
  std::vector<char> data(size);
  if (vkGetPipelineCacheData(d.device, d.pipeline_cache, &size, data.data()) != VK_SUCCESS) return;
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  const fs::path tmp = file.string() + fmt::format(".{}.tmp", getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(data.data(), std::streamsize(size));
    if (!out) {
      fs::remove(tmp, ec);
      return;
    }
  }
  fs::rename(tmp, file, ec);
  if (ec) fs::remove(tmp, ec);
}

void Device::save_pipeline_cache() {
  vulkan::save_pipeline_cache(*impl_);
}

} // namespace tierlift::vulkan
