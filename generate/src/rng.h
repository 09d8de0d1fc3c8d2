// The generator's random numbers: splitmix64, so that a listing depends on (seed, index)
// alone, on every platform and standard library (no std::uniform_*_distribution).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tierlift::gen::detail {

struct Rng {
  std::uint64_t state;
  explicit Rng(std::uint64_t seed) : state(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, n); n > 0.
  std::uint32_t below(std::uint64_t n) { return static_cast<std::uint32_t>(next() % n); }
  bool chance(double p) { return static_cast<double>(next() >> 11) * 0x1p-53 < p; }
  float unit() { return static_cast<float>(next() >> 40) * 0x1p-24f; }
  template <class T> const T& pick(const std::vector<T>& v) { return v[below(v.size())]; }
};

} // namespace tierlift::gen::detail
