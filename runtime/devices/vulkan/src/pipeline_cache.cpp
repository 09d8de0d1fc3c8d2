// The persistent pipeline cache (pipeline_cache.h).
#include "pipeline_cache.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <string>
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

// The bytes (their FNV-1a hash) this process last read from or wrote to each cache file. A
// save whose data is the same is skipped: lavapipe's cache holds its 32-byte header only, and
// writing it again after every graph run (a `tierlift test` worker runs thousands) cost about
// 15 % of a small case's CPU time in file system work, none of it useful.
std::mutex g_known_mutex;
std::map<std::string, uint64_t> g_known;

uint64_t bytes_hash(const char* data, size_t size) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (size_t i = 0; i < size; ++i)
    h = (h ^ static_cast<unsigned char>(data[i])) * 0x100000001b3ull;
  return h ^ size;
}
void remember(const fs::path& file, const std::vector<char>& data) {
  std::lock_guard lock(g_known_mutex);
  g_known[file.string()] = bytes_hash(data.data(), data.size());
}
bool known(const fs::path& file, const std::vector<char>& data) {
  std::lock_guard lock(g_known_mutex);
  auto it = g_known.find(file.string());
  return it != g_known.end() && it->second == bytes_hash(data.data(), data.size());
}

} // namespace

VkPipelineCache pipeline_cache(Device::Impl& d) {
  if (d.pipeline_cache != VK_NULL_HANDLE || d.pipeline_cache_failed) return d.pipeline_cache;
  std::vector<char> data;
  if (const fs::path file = cache_file(d); !file.empty()) {
    std::ifstream in(file, std::ios::binary);
    data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!data.empty()) remember(file, data);
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
  data.resize(size);
  if (known(file, data)) return; // the file already holds these bytes (or another run's)
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
  if (ec)
    fs::remove(tmp, ec);
  else
    remember(file, data);
}

void Device::save_pipeline_cache() {
  vulkan::save_pipeline_cache(*impl_);
}

} // namespace tierlift::vulkan
