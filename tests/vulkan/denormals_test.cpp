// NUMERICS.md rule 13 says fp32 denormals are kept on every device. The CPU device keeps
// them; lavapipe flushes them (llvmpipe sets the x86 DAZ/FTZ bits for its shader threads and
// reports neither shaderDenormPreserveFloat32 nor shaderDenormFlushToZeroFloat32). This test
// pins down both behaviours, so the differential harness's flushing of the CPU reference
// (diff_harness.h) is justified, and a driver that starts keeping denormals is noticed.
#include "diff_harness.h"

namespace tierlift::vulkan::test {
namespace {

TEST_F(VulkanTest, DenormalHandlingOfEachDevice) {
  cpu::Pass p;
  p.pixel_program = parse_listing("ps_2_0\nmul r0, c0, c1\nmov oC0, r0\n", "denorm.psh");
  ASSERT_TRUE(p.pixel_program);
  p.ps_constants.f = {{1e-40f, -1e-40f, 1e-40f, 1.0f}, {0x1p100f, 0x1p100f, 1.0f, 1.0f}};
  img::Image c(1, 1), v(1, 1);
  ASSERT_TRUE(cpu::draw(p, c, 1).ok);
  ASSERT_TRUE(dev->draw(p, v).ok);
  // CPU: kept. 1e-40f is the denormal 71362·2^-149; times 2^100 exact.
  EXPECT_EQ(c.rgba[0], 1e-40f * 0x1p100f);
  EXPECT_EQ(c.rgba[1], -1e-40f * 0x1p100f);
  EXPECT_EQ(c.rgba[2], 1e-40f);
  const bool flushed = v.rgba[0] == 0.0f;
  EXPECT_EQ(flushed, flushes(*dev));
  if (dev->name().find("llvmpipe") != std::string::npos) {
    EXPECT_TRUE(flushed) << "lavapipe keeps denormals now: NUMERICS.md rule 13 holds on it, "
                            "and diff_harness.h need not flush the CPU reference";
  }
  if (flushed) {
    EXPECT_EQ(v.rgba[0], 0.0f);
    // The flushed factor compares equal to 0, so legacy_mul (NUMERICS.md rule 8) gives +0.
    EXPECT_EQ(v.rgba[1], 0.0f);
    EXPECT_FALSE(std::signbit(v.rgba[1]));
  } else {
    EXPECT_EQ(v.rgba[0], c.rgba[0]);
  }
}

} // namespace
} // namespace tierlift::vulkan::test
