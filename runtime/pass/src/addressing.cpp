#include "tierlift/pass/addressing.h"

namespace tierlift::pass {
namespace {

// Mathematical (non-negative) modulo.
int64_t mod_floor(int64_t a, int64_t n) {
  int64_t r = a % n;
  return r < 0 ? r + n : r;
}
// −1 → 0, −2 → 1, …: the index reflected about the texture's left edge.
int64_t mirror(int64_t n) {
  return n >= 0 ? n : -(1 + n);
}

} // namespace

std::optional<int64_t> address_texel(AddressMode mode, int64_t i, int64_t n) {
  if (n <= 0) return std::nullopt;
  if (i >= 0 && i < n) return i;
  switch (mode) {
  case AddressMode::Wrap: return mod_floor(i, n);
  case AddressMode::Mirror: {
    // Period 2n: 0..n−1 forward, then n−1..0 back.
    const int64_t t = mod_floor(i, 2 * n) - n;
    return (n - 1) - mirror(t);
  }
  case AddressMode::Clamp: return i < 0 ? 0 : n - 1;
  case AddressMode::Border: return std::nullopt;
  case AddressMode::MirrorOnce: {
    const int64_t m = mirror(i);
    return m >= n ? n - 1 : m;
  }
  }
  return std::nullopt;
}

} // namespace tierlift::pass
