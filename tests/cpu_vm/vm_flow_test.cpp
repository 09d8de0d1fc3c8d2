// vs_2_0 static flow control (docs/d3d9-rules.md §5.3): loop with aL stepping, rep, nested if,
// call/callnz/ret, and the bounds that keep a broken program from hanging.
#include "vm_test_util.h"

using namespace vmtest;

namespace {
const char* kHead = "vs_2_0\ndcl_position v0\nmov oPos, v0\n";

VertexOutput run(const std::string& body, const ConstantBank& c) {
  ShaderVM vm = vm_of(parse(std::string(kHead) + body), {});
  return vm.run_vertex({}, c);
}
} // namespace

TEST(VmFlow, LoopStepsAl) {
  // defi i0 = (3, 2, 2, 0): aL = 2, 4, 6 → r4 = c0 + c2 + c4 + c6 = 0 + 1 + 10 + 100 = 111
  // (c8 = 1000 must not be read).
  const ConstantBank c = splats(10, {{2, 1}, {4, 10}, {6, 100}, {8, 1000}});
  ShaderVM vm =
      vm_of(parse(std::string("vs_2_0\ndefi i0, 3, 2, 2, 0\ndcl_position v0\nmov oPos, v0\n"
                              "mov r4, c0\nloop aL, i0\nadd r4, r4, c[aL]\nendloop\n"
                              "mov oT0, r4\n")),
            {});
  EXPECT_VEC4(vm.run_vertex({}, c).tex[0], 111, 111, 111, 111);
}

TEST(VmFlow, LoopWithOffsetAndApiIntegers) {
  // API i1 = (2, 1, 3, 0): aL = 1, 4; c[aL + 1] reads c2 and c5 → 1 + 10 = 11.
  ConstantBank c = splats(8, {{2, 1}, {5, 10}});
  c.i[1] = {2, 1, 3, 0};
  auto o = run("mov r4, c0\nloop aL, i1\nadd r4, r4, c[aL + 1]\nendloop\nmov oT0, r4\n", c);
  EXPECT_VEC4(o.tex[0], 11, 11, 11, 11);
}

TEST(VmFlow, RepRepeats) {
  // rep i0.x = 4 times r4 += c1 (= 0.5) → 2; a zero count skips the body.
  ConstantBank c = bank({{0, 0, 0, 0}, {0.5f, 0.5f, 0.5f, 0.5f}});
  c.i[0] = {4, 0, 0, 0};
  c.i[1] = {0, 0, 0, 0};
  auto o = run("mov r4, c0\nrep i0\nadd r4, r4, c1\nendrep\nmov oT0, r4\n"
               "mov r5, c0\nrep i1\nadd r5, r5, c1\nendrep\nmov oT1, r5\n",
               c);
  EXPECT_VEC4(o.tex[0], 2, 2, 2, 2);
  EXPECT_VEC4(o.tex[1], 0, 0, 0, 0);
}

TEST(VmFlow, LoopCountsClampToLegalRange) {
  // i0.x = 1000 runs 255 times (legal maximum); i1.x = −5 runs zero times.
  ConstantBank c = bank({{0, 0, 0, 0}, {1, 1, 1, 1}});
  c.i[0] = {1000, 0, 1, 0};
  c.i[1] = {-5, 0, 1, 0};
  auto o = run("mov r4, c0\nloop aL, i0\nadd r4, r4, c1\nendloop\nmov oT0, r4\n"
               "mov r5, c0\nrep i1\nadd r5, r5, c1\nendrep\nmov oT1, r5\n",
               c);
  EXPECT_EQ(o.tex[0][0], 255.0f);
  EXPECT_EQ(o.tex[1][0], 0.0f);
}

TEST(VmFlow, NestedIf) {
  // if b0 { if b1 { r4 = c1 (10) } else { r4 = c2 (20) } } else { r4 = c3 (30) }
  const char* body = "if b0\nif b1\nmov r4, c1\nelse\nmov r4, c2\nendif\nelse\nmov r4, c3\n"
                     "endif\nmov oT0, r4\n";
  ConstantBank c = bank({{}, {10, 10, 10, 10}, {20, 20, 20, 20}, {30, 30, 30, 30}});
  c.b[0] = true, c.b[1] = true;
  EXPECT_EQ(run(body, c).tex[0][0], 10.0f);
  c.b[1] = false;
  EXPECT_EQ(run(body, c).tex[0][0], 20.0f);
  c.b[0] = false;
  EXPECT_EQ(run(body, c).tex[0][0], 30.0f);
}

TEST(VmFlow, IfWithoutElseAndDefb) {
  // defb b2 = false overrides the API value true: the block is skipped → r4 stays c0 = 1.
  ConstantBank c = bank({{1, 1, 1, 1}, {5, 5, 5, 5}});
  c.b[2] = true;
  ShaderVM vm = vm_of(parse("vs_2_0\ndefb b2, false\ndcl_position v0\nmov oPos, v0\nmov r4, c0\n"
                            "if b2\nmov r4, c1\nendif\nmov oT0, r4\n"),
                      {});
  EXPECT_EQ(vm.run_vertex({}, c).tex[0][0], 1.0f);
}

TEST(VmFlow, CallCallnzRet) {
  // call l0 adds 1; callnz l1, b0 adds 10; callnz l2, !b0 adds 100.
  // b0 true: 1 + 10 = 11; b0 false: 1 + 100 = 101.
  const char* body = "mov r4, c0\ncall l0\ncallnz l1, b0\ncallnz l2, !b0\nmov oT0, r4\nret\n"
                     "label l0\nadd r4, r4, c1\nret\nlabel l1\nadd r4, r4, c2\nret\n"
                     "label l2\nadd r4, r4, c3\nret\n";
  ConstantBank c = bank({{0, 0, 0, 0}, {1, 1, 1, 1}, {10, 10, 10, 10}, {100, 100, 100, 100}});
  c.b[0] = true;
  EXPECT_EQ(run(body, c).tex[0][0], 11.0f);
  c.b[0] = false;
  EXPECT_EQ(run(body, c).tex[0][0], 101.0f);
}

TEST(VmFlow, CallInsideLoopSeesAl) {
  // loop aL = 0, 1, 2 (i0 = (3, 0, 1, 0)); the subroutine adds c[aL + 4]: 1 + 2 + 4 = 7.
  ConstantBank c = splats(8, {{4, 1}, {5, 2}, {6, 4}});
  c.i[0] = {3, 0, 1, 0};
  auto o = run("mov r4, c0\nloop aL, i0\ncall l0\nendloop\nmov oT0, r4\nret\n"
               "label l0\nadd r4, r4, c[aL + 4]\nret\n",
               c);
  EXPECT_EQ(o.tex[0][0], 7.0f);
}

TEST(VmFlow, UnmatchedFlowIsRejectedAtConstruction) {
  // A program that never passed validation: endloop with no loop.
  auto prog = parse(std::string(kHead) + "rep i0\nmov oT0, c0\nendrep\n");
  ASSERT_EQ(prog.code.size(), 4u);
  prog.code.erase(prog.code.begin() + 1); // drop the rep: endrep is unmatched
  const tierlift::ir::Result<ShaderVM> vm = ShaderVM::create(prog, {});
  ASSERT_FALSE(vm);
  EXPECT_EQ(vm.diagnostics().front().rule, "vm");
  EXPECT_NE(vm.message().find("unmatched end of loop"), std::string::npos) << vm.message();
}

TEST(VmFlow, BrokenProgramCannotHang) {
  // Three nested rep blocks of 255 (invalid: vs_2_0 allows nesting depth 1, so the
  // listing skips the validator) would run 16.6 million iterations; the loop budget of
  // ir/flow_rules.h ends them after 64242 (VmSm3Flow.IterationBudgetEndsEveryLoop works it
  // out), and oT0 is written after the loops.
  ConstantBank c = bank({{0, 0, 0, 0}, {1, 1, 1, 1}});
  c.i[0] = {255, 0, 0, 0};
  ShaderVM vm =
      vm_of(parse(std::string(kHead) + "mov r4, c0\nrep i0\nrep i0\nrep i0\nadd r4, r4, c1\n"
                                       "endrep\nendrep\nendrep\nmov oT0, r4\n",
                  false),
            {});
  auto o = vm.run_vertex({}, c);
  EXPECT_EQ(o.tex[0][0], 64242.0f);
}
