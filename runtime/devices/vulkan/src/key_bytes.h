// Internal: the byte strings the device's caches key on (the prepared-draw cache, draw_cache.h,
// and the program-reuse cache, program_reuse.h): values appended as raw bytes, floats by their
// bits (so −0 and NaN payloads stay distinct), and the pass state both caches must include.
#pragma once

#include <array>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "tierlift/pass/pass.h"

namespace tierlift::vulkan {

class KeyBytes {
public:
  template <typename T> void put(const T& v) {
    static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T> || std::is_pointer_v<T>);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &v, sizeof(T));
    key_.append(bytes, sizeof(T));
  }
  template <typename T, size_t N> void put(const std::array<T, N>& a) {
    for (const T& v : a) put(v);
  }
  void put(const std::vector<uint32_t>& words) {
    put(words.size());
    key_.append(reinterpret_cast<const char*>(words.data()), words.size() * sizeof(uint32_t));
  }
  void put(const pass::ConstantBank& bank) {
    put(bank.f.size());
    for (const pass::Vec4& v : bank.f) put(v);
    for (const auto& i : bank.i) put(i);
    put(bank.b);
  }
  // D3D9's depth/stencil state: every field a pipeline is made from.
  void put(const pass::DepthStencilState& ds) {
    put(ds.depth_test);
    put(ds.depth_write);
    put(ds.depth_func);
    put(ds.stencil_test);
    put(ds.stencil_func);
    put(ds.stencil_fail);
    put(ds.stencil_depth_fail);
    put(ds.stencil_pass);
    put(ds.stencil_ref);
    put(ds.stencil_read_mask);
    put(ds.stencil_write_mask);
  }
  std::string take() { return std::move(key_); }

private:
  std::string key_;
};

} // namespace tierlift::vulkan
