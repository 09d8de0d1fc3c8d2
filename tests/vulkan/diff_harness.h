// The differential harness: small generated listings run on the CPU device and on the Vulkan
// device over seeded random inputs that include NUMERICS.md's special values, compared value
// by value.
//
// Inputs reach the programs two ways:
//   * pixel tests: textures s0..s3 (RGBA32F, point-sampled at texel centres with modern pixel
//     centres, so every pixel reads its own texel exactly) and constants;
//   * vertex tests: one small triangle per pixel whose three vertices carry the same random
//     v1..v4; the varyings are decorated Flat on Vulkan (flat_varyings.h) and the
//     CPU device interpolates equal values to themselves, so the pixel sees the vertex result.
//
// Comparison: NaN matches NaN, ±inf must match exactly, finite values must satisfy
// |cpu − vk| ≤ 1e-5 · max(1, |cpu|, |vk|) — docs/design.md's RGBA32F target (1e-5 of full scale)
// applied per value, so one FLT_MAX in the image does not make every other value pass.
//
// Denormals: inputs carry real ones (±1e-40 and ±2^-140, in textures, constants and vertex
// inputs). The CPU device's default convention (Rounding::Llvmpipe) treats them as lavapipe
// does (NUMERICS.md rule 13: a zero of the same sign in and out of every operation, bits kept
// by data movement), so the reference runs on exactly the inputs the device gets.
#pragma once

#include <cfloat>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "flat_varyings.h"
#include "vk_test_util.h"

namespace tierlift::vulkan::test {

// A listing on one line ("mov r3, r0; add r3, r3, r1"): how a difference test's case prints
// in test listings (its PrintTo), where a newline would end the entry.
inline std::string one_line(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c != '\n')
      out += c;
    else if (!out.empty() && out.back() != ' ')
      out += "; ";
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  return out;
}

inline constexpr uint32_t kDiffW = 16, kDiffH = 16;

// NUMERICS.md's special values (and their neighbours) as inputs.
inline const std::vector<float>& special_values() {
  static const std::vector<float> v = {0.0f,
                                       -0.0f,
                                       1.0f,
                                       -1.0f,
                                       0.5f,
                                       -4.0f,
                                       std::numeric_limits<float>::infinity(),
                                       -std::numeric_limits<float>::infinity(),
                                       std::numeric_limits<float>::quiet_NaN(),
                                       FLT_MAX,
                                       -FLT_MAX,
                                       FLT_MIN,
                                       1e-40f, // denormals
                                       -1e-40f,
                                       0x1p-140f,
                                       -0x1p-140f,
                                       128.0f, // exp overflow
                                       -130.0f,
                                       1e20f,
                                       -1e-20f};
  return v;
}

struct Rng {
  uint64_t state;
  explicit Rng(uint64_t seed) : state(seed) {}
  float unit() { return img::unit_float24(img::splitmix64(state)); }
  float range(float lo, float hi) { return lo + (hi - lo) * unit(); }
  // Uniform in [lo, hi] with probability 1 − p_special, else a special value.
  float value(float lo, float hi, float p_special) {
    if (unit() < p_special) {
      const auto& s = special_values();
      return s[img::splitmix64(state) % s.size()];
    }
    return range(lo, hi);
  }
};

struct InputRange {
  float lo = -4, hi = 4;
  float p_special = 0.25f; // 0: no special values
};

inline std::shared_ptr<const img::Image> random_texture(uint64_t seed, InputRange r,
                                                        uint32_t w = kDiffW, uint32_t h = kDiffH) {
  Rng rng(seed);
  auto im = std::make_shared<img::Image>(w, h);
  for (float& v : im->rgba) v = rng.value(r.lo, r.hi, r.p_special);
  return im;
}

inline std::vector<cpu::Vec4> random_constants(uint64_t seed, size_t n, InputRange r) {
  Rng rng(seed);
  std::vector<cpu::Vec4> c(n);
  for (auto& v : c)
    for (float& x : v) x = rng.value(r.lo, r.hi, r.p_special);
  return c;
}

// Per-value comparison (see the header comment). Returns the largest scaled difference
// |a − b| / max(1, |a|, |b|) over finite pairs, and counts mismatching special values.
struct ValueDiff {
  double max_scaled = 0, max_abs_small = 0; // max_abs_small: over pairs with |a|, |b| ≤ 1
  uint64_t special_mismatch = 0, values = 0;
  std::string first_bad;
};

inline ValueDiff compare_values(const img::Image& a, const img::Image& b) {
  ValueDiff d;
  for (size_t i = 0; i < a.rgba.size() && i < b.rgba.size(); ++i) {
    float x = a.rgba[i], y = b.rgba[i];
    ++d.values;
    bool bad = false;
    if (std::isnan(x) || std::isnan(y) || std::isinf(x) || std::isinf(y)) {
      bad = !((std::isnan(x) && std::isnan(y)) || x == y);
      if (bad) ++d.special_mismatch;
    } else {
      double diff = std::fabs(double(x) - double(y));
      double scaled = diff / std::max({1.0, std::fabs(double(x)), std::fabs(double(y))});
      d.max_scaled = std::max(d.max_scaled, scaled);
      if (std::fabs(x) <= 1 && std::fabs(y) <= 1) d.max_abs_small = std::max(d.max_abs_small, diff);
      bad = scaled > 1e-5;
    }
    if (bad && d.first_bad.empty())
      d.first_bad = fmt::format("pixel ({}, {}) channel {}: cpu {} vulkan {}", (i / 4) % a.width,
                                (i / 4) / a.width, i % 4, x, y);
  }
  return d;
}

// Does the device flush denormal inputs of arithmetic? c0 = 1e-40 times c1 = 2^100 is
// 1.27e-10 when denormals are kept and 0 when they are flushed.
inline bool device_flushes_denormals(vulkan::Device& dev) {
  cpu::Pass p;
  p.pixel_program = parse_listing("ps_2_0\nmul r0, c0, c1\nmov oC0, r0\n", "probe.psh");
  p.ps_constants.f = {{1e-40f, 1e-40f, 1e-40f, 1e-40f}, {0x1p100f, 0x1p100f, 0x1p100f, 0x1p100f}};
  img::Image t(1, 1);
  ir::Result<pass::DrawReport> r = dev.draw(p, t);
  EXPECT_TRUE(r.ok()) << r.message();
  return t.rgba[0] == 0.0f;
}

inline bool flushes(vulkan::Device& dev) {
  static const bool f = device_flushes_denormals(dev);
  return f;
}

struct DiffSetup {
  std::vector<std::shared_ptr<const img::Image>> textures; // stage s = index
  cpu::Filter filter = cpu::Filter::Point;
  std::vector<cpu::Vec4> vs_c, ps_c;
  std::array<bool, cpu::kMaxSamplers> projected{};
  bool per_pixel_vertices = false; // vertex tests
  InputRange vertex_range;
  uint64_t seed = 1;
  img::Format format = img::Format::RGBA32F;
};

// n textures on stages 0..n-1, texture k drawn from s.seed·10 + k.
inline void add_random_textures(DiffSetup& s, uint32_t n, InputRange r, uint32_t w = kDiffW,
                                uint32_t h = kDiffH) {
  for (uint32_t k = 0; k < n; ++k) s.textures.push_back(random_texture(s.seed * 10 + k, r, w, h));
}

// The first word of each line of `listing`, cut at the first of `ends`: the mnemonics a case
// table covers, for the tests that every opcode of a family has a case.
inline void add_mnemonics(std::set<std::string>& covered, const std::string& listing,
                          const char* ends) {
  std::istringstream in(listing);
  std::string line;
  while (std::getline(in, line)) covered.insert(line.substr(0, line.find_first_of(ends)));
}

// The full-screen quad (v0 corners, v3 quad-uv) or one triangle per pixel carrying random
// v1..v4 (see the header comment).
inline void set_geometry(cpu::Pass& pass, const DiffSetup& s) {
  if (!s.per_pixel_vertices) {
    cpu::set_full_screen_quad(pass, 0);
    for (size_t k = 0; k < pass.vertices.size(); ++k) pass.vertices[k].v[3] = cpu::kQuadUV[k];
    return;
  }
  Rng rng(s.seed * 7919 + 3);
  pass.vertices.clear();
  pass.triangles.clear();
  auto clip = [](double sx, double sy) {
    return cpu::Vec4{float(2 * sx / kDiffW - 1), float(1 - 2 * sy / kDiffH), 0, 1};
  };
  for (uint32_t j = 0; j < kDiffH; ++j)
    for (uint32_t i = 0; i < kDiffW; ++i) {
      cpu::VertexInput in;
      for (uint32_t r = 1; r <= 4; ++r)
        for (float& x : in.v[r])
          x = rng.value(s.vertex_range.lo, s.vertex_range.hi, s.vertex_range.p_special);
      // Modern centre (i + 0.5, j + 0.5) lies strictly inside; no other centre does. The
      // corners are multiples of 1/4 pixel, exact on the 1/256 grid.
      const double pts[3][2] = {{i - 0.25, j - 0.25}, {i + 1.5, j - 0.25}, {i - 0.25, j + 1.5}};
      for (const auto& p : pts) {
        in.v[0] = clip(p[0], p[1]);
        pass.vertices.push_back(in);
      }
    }
}

struct DiffResult {
  bool ok = false;
  ValueDiff diff;
  img::Image cpu, vk;
};

// run_diff with a last change to the pass (sampler states, conventions) before drawing.
template <class Adjust>
DiffResult run_diff_with(vulkan::Device& dev, const std::string& vs_text,
                         const std::string& ps_text, const DiffSetup& s, Adjust adjust) {
  DiffResult out;
  cpu::Pass pass;
  pass.vertex_program = parse_listing(vs_text, "diff.vsh");
  pass.pixel_program = parse_listing(ps_text, "diff.psh");
  if (!pass.vertex_program || !pass.pixel_program) return out;
  pass.vs_constants.f = s.vs_c;
  pass.ps_constants.f = s.ps_c;
  for (size_t k = 0; k < s.textures.size() && k < cpu::kMaxSamplers; ++k) {
    pass.textures[k].image = s.textures[k];
    pass.textures[k].sampler.filter = s.filter;
    pass.textures[k].sampler.address_u = pass.textures[k].sampler.address_v =
        cpu::AddressMode::Clamp;
    pass.textures[k].stage.projected = s.projected[k];
  }
  set_geometry(pass, s);
  pass.conventions.pixel_center = ir::PixelCenter::Modern;
  pass.conventions.subtexel_bits = int(dev.subtexel_bits());
  adjust(pass);
  // Vulkan draws the same pass, its varyings flat for the vertex tests.
  cpu::Pass vk_pass = pass;
  if (s.per_pixel_vertices) {
    vk_pass.pixel_spirv = flat_pixel_spirv(pass);
    EXPECT_NE(vk_pass.pixel_spirv, nullptr);
  }
  out.cpu = img::Image(kDiffW, kDiffH, s.format);
  out.vk = out.cpu;
  ir::Result<cpu::DrawStats> st = cpu::draw(pass, out.cpu, 2);
  EXPECT_TRUE(st.ok()) << st.message();
  ir::Result<pass::DrawReport> r = dev.draw(vk_pass, out.vk);
  EXPECT_TRUE(r.ok()) << r.message();
  if (!st.ok() || !r.ok()) return out;
  out.diff = compare_values(out.cpu, out.vk);
  out.ok = true;
  return out;
}

inline DiffResult run_diff(vulkan::Device& dev, const std::string& vs_text,
                           const std::string& ps_text, const DiffSetup& s) {
  return run_diff_with(dev, vs_text, ps_text, s, [](cpu::Pass&) {});
}

// Family maxima, printed once at exit (for the report).
struct FamilyMax {
  std::string name;
  double max_scaled = 0, max_abs_small = 0;
  int cases = 0;
  explicit FamilyMax(std::string n) : name(std::move(n)) {}
  void add(const ValueDiff& d) {
    max_scaled = std::max(max_scaled, d.max_scaled);
    max_abs_small = std::max(max_abs_small, d.max_abs_small);
    ++cases;
  }
  ~FamilyMax() {
    if (cases)
      std::printf("[vk-agreement] family %-24s %3d cases: max scaled diff %.3g, max abs (|v|<=1) "
                  "%.3g\n",
                  name.c_str(), cases, max_scaled, max_abs_small);
  }
};

// Share of pixels whose four values are identical on both devices (NaN matches NaN), and the
// largest absolute difference over finite pairs: the per-case figures of the report lines.
inline void print_case_agreement(const DiffResult& r, const std::string& what) {
  size_t same = 0, pixels = r.cpu.rgba.size() / 4;
  double max_abs = 0;
  for (size_t p = 0; p < pixels; ++p) {
    bool all = true;
    for (size_t k = 0; k < 4; ++k) {
      float x = r.cpu.rgba[p * 4 + k], y = r.vk.rgba[p * 4 + k];
      all = all && (x == y || (std::isnan(x) && std::isnan(y)));
      if (std::isfinite(x) && std::isfinite(y))
        max_abs = std::max(max_abs, std::fabs(double(x) - double(y)));
    }
    same += all;
  }
  std::printf("[vk-agreement] case %-32s max abs %.3g, identical %.2f %%\n", what.c_str(), max_abs,
              pixels ? 100.0 * double(same) / double(pixels) : 0.0);
}

inline void expect_agree(const DiffResult& r, const std::string& what) {
  ASSERT_TRUE(r.ok) << what;
  EXPECT_EQ(r.diff.special_mismatch, 0u) << what << ": " << r.diff.first_bad;
  EXPECT_LE(r.diff.max_scaled, 1e-5) << what << ": " << r.diff.first_bad;
  if (r.diff.max_scaled > 1e-6)
    std::printf("[vk-agreement] note: %s: max scaled diff %.3g\n", what.c_str(), r.diff.max_scaled);
}

// expect_agree, and the case's differences counted into its family's maxima.
inline void expect_agree(const DiffResult& r, const std::string& what, FamilyMax& family) {
  expect_agree(r, what);
  family.add(r.diff);
}

} // namespace tierlift::vulkan::test
