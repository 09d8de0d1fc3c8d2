// Shared by the Vulkan tests: one validated device for the whole test program (destroyed at
// its end, where the layer's leak report fails the program), a fixture that fails a test
// when the validation layer said anything, listing loaders, and the CPU/Vulkan
// comparison of one pass.
#pragma once

#include <dlfcn.h>
#include <gtest/gtest.h>
#include <link.h>

#include <bit>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "skip_policy.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/image/builtin.h"
#include "tierlift/image/compare.h"
#include "tierlift/pass/setup.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::vulkan::test {

// Devices the test program keeps until it ends. DeviceTeardown (below) destroys them after
// the last test, with the validation layer still watching: vkDestroyDevice and
// vkDestroyInstance report every Vulkan object tierlift created and never destroyed, and any
// message then fails the program.
struct ProgramDevices {
  std::vector<std::unique_ptr<Device>> devices;
  std::vector<std::string> messages_at_destruction;
  std::mutex mutex;
};
inline ProgramDevices& program_devices() {
  static ProgramDevices d;
  return d;
}

// Keeps every shared object loaded now (lavapipe, LLVM, the validation layer) loaded for the
// rest of the process: vkDestroyInstance would dlclose the driver and the layer, and the
// bytes they keep for the process's lifetime would then reach LeakSanitizer from an
// "<unknown module>" that no suppression by library name matches.
inline void pin_loaded_modules() {
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void*) {
        if (info->dlpi_name && *info->dlpi_name)
          (void)dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD);
        return 0;
      },
      nullptr);
}

// A validated device owned by the program (destroyed at its end), or why there is none
// (ir::failed_with(r, kNoDeviceRule): simply no device).
inline ir::Result<Device*> program_device(DeviceOptions o) {
  o.validation = true;
  o.on_destroyed = [](const std::vector<std::string>& messages) {
    ProgramDevices& p = program_devices();
    std::lock_guard<std::mutex> lock(p.mutex);
    p.messages_at_destruction.insert(p.messages_at_destruction.end(), messages.begin(),
                                     messages.end());
  };
  ir::Result<std::unique_ptr<Device>> d = Device::create(o);
  if (!d) return std::move(d).failure();
  pin_loaded_modules();
  ProgramDevices& p = program_devices();
  std::lock_guard<std::mutex> lock(p.mutex);
  p.devices.push_back(std::move(d).value());
  return p.devices.back().get();
}

class DeviceTeardown : public ::testing::Environment {
public:
  void TearDown() override {
    ProgramDevices& p = program_devices();
    std::vector<std::unique_ptr<Device>> devices;
    {
      std::lock_guard<std::mutex> lock(p.mutex);
      devices.swap(p.devices);
    }
    devices.clear(); // reports into messages_at_destruction
    std::lock_guard<std::mutex> lock(p.mutex);
    for (const auto& m : p.messages_at_destruction)
      ADD_FAILURE() << "validation layer at device destruction: " << m;
    p.messages_at_destruction.clear();
  }
};
// Registered once per program (an inline variable), before main runs the tests.
inline const bool kDeviceTeardownRegistered =
    (::testing::AddGlobalTestEnvironment(new DeviceTeardown), true);

// The device every test shares (instance creation with validation costs ~100 ms).
inline const ir::Result<Device*>& shared_device() {
  static const ir::Result<Device*> shared = program_device({});
  return shared;
}

class VulkanTest : public ::testing::Test {
protected:
  // The device the fixture runs on; a fixture needing other validation options overrides it.
  virtual const ir::Result<vulkan::Device*>& acquire_device() { return shared_device(); }

  void SetUp() override {
    const ir::Result<vulkan::Device*>& got = acquire_device();
    if (!got) {
      // Only a machine without any Vulkan device may skip (and not under
      // TIERLIFT_REQUIRE_VULKAN); a missing validation layer or any other failure is a test
      // failure.
      if (ir::failed_with(got, kNoDeviceRule))
        TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, got.message());
      FAIL() << got.message();
    }
    dev = *got;
    dev->clear_messages();
  }
  void TearDown() override {
    if (!dev) return;
    for (const auto& m : dev->messages()) ADD_FAILURE() << "validation layer: " << m;
    dev->clear_messages();
  }
  vulkan::Device* dev = nullptr;
};

inline std::shared_ptr<const ir::Program> parse_listing(const std::string& text,
                                                        const std::string& name) {
  auto r = assembly::parse_text(text, name);
  if (!r.program) {
    ADD_FAILURE() << name << ": " << ir::render_text(r.diags, r.sources);
    return nullptr;
  }
  if (!assembly::validate(*r.program, r.diags)) {
    ADD_FAILURE() << name << ": " << ir::render_text(r.diags, r.sources) << "\n" << text;
    return nullptr;
  }
  return std::make_shared<const ir::Program>(*r.program);
}

inline std::shared_ptr<const ir::Program> gpugems_listing(const std::string& file) {
  std::ifstream in(std::string(TIERLIFT_SOURCE_DIR) + "/listings/gpugems21/" + file);
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_listing(ss.str(), file);
}

struct TwoWays {
  img::Image cpu, vk;
  img::Comparison cmp;
  bool ok = false;
  double cpu_ms = 0, vk_ms = 0;
};

// Draws `pass` on the CPU device and on `dev` into targets of the given size and format
// (both start as `initial` when given, else zero) and compares them.
inline TwoWays draw_both(vulkan::Device& dev, const cpu::Pass& pass, uint32_t w, uint32_t h,
                         img::Format format, const img::Image* initial = nullptr) {
  TwoWays t;
  t.cpu = initial ? *initial : img::Image(w, h, format);
  t.cpu.format = format;
  t.vk = t.cpu;
  auto start = std::chrono::steady_clock::now();
  ir::Result<cpu::DrawStats> s = cpu::draw(pass, t.cpu, 2);
  t.cpu_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(s.ok()) << s.message();
  ir::Result<pass::DrawReport> r = dev.draw(pass, t.vk);
  EXPECT_TRUE(r.ok()) << r.message();
  if (r) t.vk_ms = r->setup_ms + r->draw_ms;
  auto c = img::compare(t.cpu, t.vk);
  EXPECT_TRUE(c) << c.message();
  if (c) t.cmp = *c;
  t.ok = s.ok() && r.ok() && c.ok();
  return t;
}

// The rules that model lavapipe bit for bit (NUMERICS.md rules 35, 39, 40) have nothing to
// compare on another device (a GPU picked for the tests), so their tests skip there; under
// TIERLIFT_REQUIRE_VULKAN (CI, whose device is lavapipe) another device fails them instead, so
// a skip cannot turn that run green. Like GTEST_SKIP it returns from the test body.
#define TIERLIFT_SKIP_UNLESS_LAVAPIPE(device)                                                      \
  do {                                                                                             \
    if ((device)->name().find("llvmpipe") == std::string::npos)                                    \
      TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan,                              \
                                    "the rule models lavapipe; device is " + (device)->name());    \
  } while (0)

// The same bits, or both NaN whatever their payloads.
inline bool same_float_bits(float x, float y) {
  return std::bit_cast<uint32_t>(x) == std::bit_cast<uint32_t>(y) || (x != x && y != y);
}

// How many values differ in their bits (same_float_bits) between `a` and `b`, counting the
// first `channels` channels of each pixel: the images the three-way draws give.
inline size_t values_off(const img::Image& a, const img::Image& b, int channels) {
  size_t n = 0;
  for (size_t i = 0; i < a.rgba.size() && i < b.rgba.size(); ++i)
    n += static_cast<int>(i % 4) < channels && !same_float_bits(a.rgba[i], b.rgba[i]);
  return n;
}

// A pass whose pixel i reads texel i of `tex` (POINT, CLAMP, modern pixel centres: point
// sampling at (i + ½)/W) through `pixel_listing`, which reads the quad's uv from t0 (ps_2_0)
// or from a dcl_texcoord v0 (ps_3_0), and a vertex program of the same model passing it on.
inline cpu::Pass per_texel_pass(std::shared_ptr<const img::Image> tex,
                                const std::string& pixel_listing, const std::string& name) {
  cpu::Pass p;
  const bool sm3 = pixel_listing.starts_with("ps_3_0");
  p.vertex_program = parse_listing(
      sm3 ? "vs_3_0\ndcl_position v0\ndcl_texcoord v3\ndcl_position o0\ndcl_texcoord o1\n"
            "mov o0, v0\nmov o1, v3\n"
          : "vs_2_0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\nmov oT0, v3\n",
      name + ".vsh");
  p.pixel_program = parse_listing(pixel_listing, name + ".psh");
  p.textures[0].image = std::move(tex);
  p.textures[0].sampler.filter = cpu::Filter::Point;
  p.textures[0].sampler.address_u = p.textures[0].sampler.address_v = cpu::AddressMode::Clamp;
  cpu::set_full_screen_quad(p, 0);
  for (size_t k = 0; k < p.vertices.size(); ++k) p.vertices[k].v[3] = cpu::kQuadUV[k];
  p.conventions.pixel_center = ir::PixelCenter::Modern;
  return p;
}

// `pass` drawn on `dev` and on the CPU device under the pass's rounding and under
// Rounding::Exact, each into a copy of `initial`: what a lavapipe-model test compares.
struct ThreeWays {
  img::Image vk, cpu, cpu_exact;
  bool ok = false;
};
inline ThreeWays draw_three_ways(vulkan::Device& dev, const cpu::Pass& pass,
                                 const img::Image& initial) {
  ThreeWays t{initial, initial, initial};
  ir::Result<pass::DrawReport> r = dev.draw(pass, t.vk);
  EXPECT_TRUE(r.ok()) << r.message();
  ir::Result<cpu::DrawStats> c = cpu::draw(pass, t.cpu, 2);
  EXPECT_TRUE(c.ok()) << c.message();
  cpu::Pass exact = pass;
  exact.conventions.rounding = ir::Rounding::Exact;
  ir::Result<cpu::DrawStats> e = cpu::draw(exact, t.cpu_exact, 2);
  EXPECT_TRUE(e.ok()) << e.message();
  t.ok = r.ok() && c.ok() && e.ok();
  return t;
}

// Records the family's measured maximum for the report (printed at the end of a test).
inline void report(const std::string& family, const img::Comparison& c) {
  std::printf("[vk-agreement] %-40s max abs %.3g, identical %.4f %%\n", family.c_str(),
              c.max_abs_all, 100.0 * c.identical_share);
}

} // namespace tierlift::vulkan::test
