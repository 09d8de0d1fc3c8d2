// ShaderVM::run_pixel with an InstructionTrace: each instruction's destination after it ran,
// computed here by hand; co-issued halves both recorded; instructions without a register
// destination left at zero runs; the output the same as an untraced run.
#include "vm_test_util.h"

namespace {

using namespace vmtest;
using tierlift::cpu::InstructionTrace;

TEST(VmTrace, RecordsEachDestinationAfterItsWrite) {
  const ShaderVM vm = make_vm("ps_2_0\n"
                              "def c0, 0.5, 2, -1, 4\n"
                              "dcl t0\n"
                              "mov r0, t0\n"         // (0.25, 0.75, 1, 1)
                              "mad r0, r0, c0, c0\n" // (0.625, 3.5, -2, 8)
                              "add r1.yz, r0, -t0\n" // r1 = (0, 2.75, -3, 0)
                              "rcp r2.w, c0.y\n"     // r2 = (0, 0, 0, 0.5)
                              "mov oC0, r0\n");
  const PixelInput in = coords({{0.25f, 0.75f, 1, 1}});
  const ConstTextures tex;
  InstructionTrace trace;
  const PixelOutput out = vm.run_pixel(in, {}, tex, trace);
  ASSERT_EQ(trace.value.size(), 5u);
  EXPECT_EQ(trace.value[0], (Vec4{0.25f, 0.75f, 1, 1}));
  EXPECT_EQ(trace.value[1], (Vec4{0.25f * 0.5f + 0.5f, 0.75f * 2 + 2, 1 * -1 - 1, 1 * 4 + 4}));
  EXPECT_EQ(trace.value[2], (Vec4{0, 3.5f - 0.75f, -2 - 1, 0}));
  EXPECT_EQ(trace.value[3], (Vec4{0, 0, 0, 0.5f}));
  EXPECT_EQ(trace.value[4], (Vec4{0.625f, 3.5f, -2, 8}));
  EXPECT_EQ(trace.hits, (std::vector<uint32_t>{1, 1, 1, 1, 1}));
  EXPECT_EQ(out.color[0], run_ps(vm, in).color[0]); // tracing changes no result
}

TEST(VmTrace, CoIssuedHalvesAreBothRecorded) {
  const ShaderVM vm = make_vm("ps_1_1\n"
                              "def c0, 0.5, 0.25, 0.125, 0.25\n"
                              "def c1, 0.5, 0.5, 0.5, 0.5\n"
                              "mul r0.rgb, c0, c1\n"
                              "+add r0.a, c0, c1\n");
  const ConstTextures tex;
  InstructionTrace trace;
  vm.run_pixel({}, {}, tex, trace);
  ASSERT_EQ(trace.hits, (std::vector<uint32_t>{1, 1}));
  // The pair reads before either half writes; both rows hold r0 after the pair
  // (0.5·0.5, 0.25·0.5, 0.125·0.5; 0.25 + 0.5).
  const Vec4 r0{0.25f, 0.125f, 0.0625f, 0.75f};
  EXPECT_EQ(trace.value[0], r0);
  EXPECT_EQ(trace.value[1], r0);
}

TEST(VmTrace, TexkillWithoutARegisterWriteStillCountsWhatRan) {
  const ShaderVM vm = make_vm("ps_2_0\n"
                              "dcl t0\n"
                              "texkill t0\n"
                              "mov r0, t0\n"
                              "mov oC0, r0\n");
  const ConstTextures tex;
  InstructionTrace trace;
  const PixelOutput out = vm.run_pixel(coords({{1, 2, 3, 4}}), {}, tex, trace);
  EXPECT_FALSE(out.discarded);
  ASSERT_EQ(trace.hits.size(), 3u);
  EXPECT_EQ(trace.hits[1], 1u);
  EXPECT_EQ(trace.value[2], (Vec4{1, 2, 3, 4}));
}

} // namespace
