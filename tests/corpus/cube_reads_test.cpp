// The differential run reads cubes as it reads 2D textures (linear on odd input sets) on a
// device that filters each cube face on its own, and falls back to point reads on one that
// filters across face edges, which refuses a linear cube read (NUMERICS.md rule T4).
#include <gtest/gtest.h>

#include <string>

#include "skip_policy.h"
#include "tierlift/corpus/stages.h"
#include "tierlift/vulkan/device.h"
#include "tierlift/vulkan/process_device.h"

namespace tierlift::corpus {
namespace {

// Two cube reads, one at a computed direction, and ps_1_1's texm3x3tex, which reads a cube.
const char* const kCubeListings[] = {
    "ps_2_0\ndcl t0\ndcl t1\ndcl_cube s0\ndcl_cube s1\nmov r1, t1\nadd r1, t0, r1\n"
    "texld r0, r1, s0\nmul r2, r1, c0\ntexld r3, r2, s1\nadd r0, r0, r3\nmov oC0, r0\n",
    "ps.1.1\ntex t0\ntexm3x3pad t1, t0_bx2\ntexm3x3pad t2, t0_bx2\ntexm3x3tex t3, t0_bx2\n"
    "mov r0, t3\n",
};

void expect_cube_listings_pass(vulkan::Device* device) {
  StageOptions o;
  o.device = device;
  o.input_sets = 6; // three of them linear
  for (const char* text : kCubeListings) {
    const CaseResult r = run_listing("cube", "cube.psh", text, o);
    ASSERT_EQ(r.stages.back().stage, kStageDiff) << text;
    EXPECT_EQ(r.stages.back().verdict, Verdict::Pass) << text << r.stages.back().message;
  }
}

TEST(CubeReads, DifferentialRunPassesWithEachFaceFilteredAlone) {
  ir::Result<vulkan::Device*> d = vulkan::process_device({});
  if (!d) TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, d.message());
  // Lavapipe (CI's device) offers VK_EXT_non_seamless_cube_map: only another device skips.
  if (!(*d)->cube_faces_filtered_alone()) {
    ASSERT_FALSE((*d)->name().starts_with("llvmpipe")) << "lavapipe filters cubes per face";
    GTEST_SKIP() << (*d)->name() << " filters across edges";
  }
  expect_cube_listings_pass(*d);
}

// As on a Vulkan device without VK_EXT_non_seamless_cube_map: the run reads cubes with point
// filtering, so no input set is refused.
TEST(CubeReads, DifferentialRunReadsPointCubesOnADeviceFilteringAcrossEdges) {
  if (!vulkan::process_device({}))
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device");
  // Kept for the life of the process, as process_device keeps its devices (the driver stays
  // loaded until exit).
  static vulkan::Device* across = [] {
    vulkan::DeviceOptions o;
    o.per_face_cubes = false;
    ir::Result<std::unique_ptr<vulkan::Device>> made = vulkan::Device::create(o);
    return made ? made->release() : nullptr;
  }();
  ASSERT_NE(across, nullptr);
  ASSERT_FALSE(across->cube_faces_filtered_alone());
  expect_cube_listings_pass(across);
}

} // namespace
} // namespace tierlift::corpus
