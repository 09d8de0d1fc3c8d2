// Built-in textures: made in code, identical on every platform (no std distributions).
#include <fmt/format.h>

#include "tierlift/image/builtin.h"

namespace tierlift::img {

uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Top 24 bits → k / 2^24: exact in float, so the texel values do not depend on rounding.
float unit_float24(uint64_t bits) {
  return static_cast<float>(bits >> 40) * 0x1p-24f;
}

namespace {
void fill(Image& im, float r, float g, float b, float a) {
  for (size_t i = 0; i < im.rgba.size(); i += 4) {
    im.rgba[i] = r;
    im.rgba[i + 1] = g;
    im.rgba[i + 2] = b;
    im.rgba[i + 3] = a;
  }
}
void set(Image& im, uint32_t x, uint32_t y, float v) {
  float* p = im.at(x, y);
  p[0] = p[1] = p[2] = v;
  p[3] = 1.0f;
}
} // namespace

Image builtin_impulse(uint32_t width, uint32_t height) {
  Image im(width, height);
  fill(im, 0, 0, 0, 1);
  if (width && height) set(im, width / 2, height / 2, 1.0f);
  return im;
}

Image builtin_checker(uint32_t width, uint32_t height) {
  Image im(width, height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) set(im, x, y, ((x / 8 + y / 8) % 2 == 0) ? 1.0f : 0.0f);
  return im;
}

Image builtin_ramp(uint32_t width, uint32_t height) {
  Image im(width, height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x)
      set(im, x, y, static_cast<float>((x + 0.5) / static_cast<double>(width)));
  return im;
}

Image builtin_noise(uint32_t width, uint32_t height, uint64_t seed) {
  Image im(width, height);
  uint64_t state = seed;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      float* p = im.at(x, y);
      for (int c = 0; c < 3; ++c) p[c] = unit_float24(splitmix64(state));
      p[3] = 1.0f;
    }
  return im;
}

bool is_builtin_spec(std::string_view spec) {
  return spec.starts_with(kBuiltinPrefix);
}

namespace {

std::optional<uint64_t> parse_uint(std::string_view t, uint64_t max) {
  if (t.empty() || t.size() > 20) return std::nullopt;
  uint64_t v = 0;
  for (char c : t) {
    if (c < '0' || c > '9') return std::nullopt;
    uint64_t d = static_cast<uint64_t>(c - '0');
    if (v > (max - d) / 10) return std::nullopt;
    v = v * 10 + d;
  }
  return v;
}

} // namespace

ImageResult make_builtin(std::string_view spec) {
  auto fail = [&](std::string why) -> ImageResult {
    return ir::fail(std::string(spec), std::string(kImageRule), fmt::format("{}: {}", spec, why));
  };
  if (!is_builtin_spec(spec)) return fail("not a builtin texture (expected builtin:NAME)");
  std::string_view rest = spec.substr(kBuiltinPrefix.size());
  std::vector<std::string_view> parts;
  for (size_t start = 0;;) {
    size_t colon = rest.find(':', start);
    parts.push_back(rest.substr(start, colon == rest.npos ? rest.npos : colon - start));
    if (colon == rest.npos) break;
    start = colon + 1;
  }
  std::string_view name = parts[0];
  const bool noise = name == "noise";
  if (name != "impulse" && name != "checker" && name != "ramp" && !noise)
    return fail(
        fmt::format("unknown builtin texture '{}' (known: impulse, checker, ramp, noise)", name));
  if (parts.size() > (noise ? 3u : 2u)) return fail("too many ':' fields");
  uint32_t w = kBuiltinDefaultSize, h = kBuiltinDefaultSize;
  if (parts.size() >= 2) {
    std::string_view size = parts[1];
    size_t x = size.find('x');
    if (x == size.npos) return fail(fmt::format("bad size '{}' (expected WxH)", size));
    auto pw = parse_uint(size.substr(0, x), kMaxDimension);
    auto ph = parse_uint(size.substr(x + 1), kMaxDimension);
    if (!pw || !ph || *pw == 0 || *ph == 0)
      return fail(fmt::format("bad size '{}' (W and H must be 1..{})", size, kMaxDimension));
    w = static_cast<uint32_t>(*pw);
    h = static_cast<uint32_t>(*ph);
  }
  uint64_t seed = 1;
  if (parts.size() == 3) {
    auto s = parse_uint(parts[2], UINT64_MAX);
    if (!s) return fail(fmt::format("bad seed '{}' (expected a decimal number)", parts[2]));
    seed = *s;
  }
  if (name == "impulse") return ImageResult(builtin_impulse(w, h));
  if (name == "checker") return ImageResult(builtin_checker(w, h));
  if (name == "ramp") return ImageResult(builtin_ramp(w, h));
  return ImageResult(builtin_noise(w, h, seed));
}

ImageResult load_texture(const std::string& spec_or_path) {
  if (is_builtin_spec(spec_or_path)) return make_builtin(spec_or_path);
  return read_image(spec_or_path);
}

} // namespace tierlift::img
