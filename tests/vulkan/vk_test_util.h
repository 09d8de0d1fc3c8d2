// Shared by the Vulkan tests: one validated device for the whole test program, a fixture that
// fails a test when the validation layer said anything, listing loaders, and the CPU/Vulkan
// comparison of one pass.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "tierlift/asm/parser.h"
#include "tierlift/asm/validator.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/cpu/run_job.h"
#include "tierlift/image/builtin.h"
#include "tierlift/image/compare.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::vulkan::test {

// The device every test shares (instance creation with validation costs ~100 ms). nullptr
// when no Vulkan device exists at all; `error` then says why. It is deliberately never
// destroyed: destroying the last instance at exit unloads the driver (dlclose), and the few
// bytes Mesa keeps for the process's lifetime then show up in LeakSanitizer as leaks from an
// "<unknown module>"; kept alive, they stay reachable.
inline vulkan::Device* shared_device(std::string* error) {
  static std::string err;
  static vulkan::Device* dev = [] {
    DeviceOptions o;
    o.validation = true;
    return Device::create(o, &err).release();
  }();
  if (error) *error = err;
  return dev;
}

class VulkanTest : public ::testing::Test {
protected:
  // The device the fixture runs on; a fixture needing other validation options overrides it.
  virtual vulkan::Device* acquire_device(std::string* error) { return shared_device(error); }

  void SetUp() override {
    std::string err;
    dev = acquire_device(&err);
    if (!dev) {
      // Only a machine without any Vulkan device may skip; a missing validation layer or any
      // other failure is a test failure.
      if (err.find("no Vulkan device found") != std::string::npos) GTEST_SKIP() << err;
      FAIL() << err;
    }
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
  auto r = as::parse_text(text, name);
  if (!r.program) {
    ADD_FAILURE() << name << ": " << ir::render_text(r.diags, r.sources);
    return nullptr;
  }
  if (!as::validate(*r.program, r.diags)) {
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
                         img::Format format, const img::Image* initial = nullptr,
                         const DrawOptions& options = {}) {
  TwoWays t;
  t.cpu = initial ? *initial : img::Image(w, h, format);
  t.cpu.format = format;
  t.vk = t.cpu;
  auto start = std::chrono::steady_clock::now();
  cpu::DrawStats s = cpu::draw(pass, t.cpu, 2);
  t.cpu_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(s.ok) << s.error;
  DrawResult r = dev.draw(pass, t.vk, options);
  EXPECT_TRUE(r.ok) << r.error;
  t.vk_ms = r.setup_ms + r.draw_ms;
  std::string err;
  auto c = img::compare(t.cpu, t.vk, &err);
  EXPECT_TRUE(c.has_value()) << err;
  if (c) t.cmp = *c;
  t.ok = s.ok && r.ok && c.has_value();
  return t;
}

// Records the family's measured maximum for the report (printed at the end of a test).
inline void report(const std::string& family, const img::Comparison& c) {
  std::printf("[vk-agreement] %-40s max abs %.3g, identical %.4f %%\n", family.c_str(),
              c.max_abs_all, 100.0 * c.identical_share);
}

} // namespace tierlift::vulkan::test
