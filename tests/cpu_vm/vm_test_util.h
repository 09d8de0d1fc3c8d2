// Shared helpers of the VM tests: programs come from listing text through the real parser
// (tierlift::assembly::parse_text), inputs are filled by hand, and a fake TextureUnit returns
// its coordinate so that texture-address arithmetic can be checked by hand.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"
#include "tierlift/cpu/shader_vm.h"
#include "tierlift/ir/diagnostic.h"

namespace vmtest {

using tierlift::cpu::ConstantBank;
using tierlift::cpu::PixelInput;
using tierlift::cpu::PixelOutput;
using tierlift::cpu::ShaderVM;
using tierlift::cpu::StageState;
using tierlift::cpu::TextureUnit;
using tierlift::cpu::Vec4;
using tierlift::cpu::VertexInput;
using tierlift::cpu::VertexOutput;

inline tierlift::ir::Program parse(const std::string& text, bool validate = true) {
  auto r = tierlift::assembly::parse_text(text, "<test>");
  if (!r.program) {
    ADD_FAILURE() << "listing does not parse:\n" << render_text(r.diags, r.sources) << text;
    return {};
  }
  // Test listings must be valid: each one goes through the validator (helper B's), unless
  // TIERLIFT_VM_VALIDATE=0 is set in the environment.
  const char* env = std::getenv("TIERLIFT_VM_VALIDATE");
  if (validate && (!env || *env != '0')) {
    tierlift::ir::DiagnosticSink d;
    if (!tierlift::assembly::validate(*r.program, d))
      ADD_FAILURE() << "listing does not validate:\n" << render_text(d, r.sources) << text;
  }
  return *r.program;
}

// The VM suites pin the ps_1_x range of the geforce3 preset (1), the range whose clamps their
// hand-computed values show; the default conventions have the d3d9 preset's FLT_MAX.
inline tierlift::ir::Conventions geforce3() {
  tierlift::ir::Conventions c;
  c.ps1x_max_value = 1.0f;
  return c;
}

// The VM for `program`. One the VM refuses is the calling test's failure: thrown (test code
// only; the library returns the refusal), so gtest reports the VM's reason and stops the test.
inline ShaderVM vm_of(const tierlift::ir::Program& program, const tierlift::ir::Conventions& conv) {
  tierlift::ir::Result<ShaderVM> made = ShaderVM::create(program, conv);
  if (!made) throw std::runtime_error("the VM refuses the program: " + made.message());
  return std::move(*made);
}

inline ShaderVM make_vm(const std::string& text, tierlift::ir::Conventions conv = geforce3()) {
  return vm_of(parse(text), conv);
}

// Fake texture unit: returns the coordinate itself (+ 100·stage in w when asked), so
// every sampled value shows which coordinate the instruction computed.
class EchoTextures : public TextureUnit {
public:
  StageState stages[8];
  bool tag_stage = false;
  mutable float last_bias = 0;
  mutable int last_stage = -1;
  Vec4 sample(uint32_t stage, const Vec4& coord, float lod_bias) const override {
    last_bias = lod_bias;
    last_stage = static_cast<int>(stage);
    Vec4 c = coord;
    if (tag_stage) c[3] = 100.0f * static_cast<float>(stage);
    return c;
  }
  StageState stage_state(uint32_t stage) const override { return stages[stage % 8]; }
};

// Fake texture unit returning one constant colour.
class ConstTextures : public TextureUnit {
public:
  Vec4 value{0, 0, 0, 1};
  Vec4 sample(uint32_t, const Vec4&, float) const override { return value; }
};

inline PixelOutput run_ps(const ShaderVM& vm, const PixelInput& in = {},
                          const TextureUnit* tex = nullptr, const ConstantBank& c = {}) {
  static const ConstTextures none;
  return vm.run_pixel(in, c, tex ? *tex : none);
}

inline VertexOutput run_vs(const ShaderVM& vm, const VertexInput& in = {},
                           const ConstantBank& c = {}) {
  return vm.run_vertex(in, c);
}

inline uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

inline ConstantBank bank(std::initializer_list<Vec4> c) {
  ConstantBank b;
  b.f.assign(c.begin(), c.end());
  return b;
}

// n float constants, all zero but for the (index, v) pairs, whose four components are v:
// the loop tests read a few scattered constants through c[aL].
inline ConstantBank splats(size_t n, std::initializer_list<std::pair<size_t, float>> at) {
  ConstantBank b;
  b.f.resize(n, Vec4{0, 0, 0, 0});
  for (auto [i, v] : at) b.f[i] = {v, v, v, v};
  return b;
}

// Pixel input whose texture coordinates TC0, TC1, ... are `tc` in order.
inline PixelInput coords(std::initializer_list<Vec4> tc) {
  PixelInput in;
  size_t i = 0;
  for (const Vec4& t : tc) in.tex[i++] = t;
  return in;
}

// vs_2_0 / vs_1_1 harness: c0..c3 are copied to r0..r3 (so one instruction may read
// several of them: vertex shaders have one constant read port), then `body` runs.
inline VertexOutput vs(const char* profile, const std::string& body, const ConstantBank& c,
                       tierlift::ir::Conventions conv = {}) {
  std::string text = std::string(profile) +
                     "\ndcl_position v0\nmov oPos, v0\nmov r0, c0\nmov r1, c1\n"
                     "mov r2, c2\nmov r3, c3\n" +
                     body;
  ShaderVM vm = vm_of(parse(text), conv);
  return vm.run_vertex(VertexInput{}, c);
}
inline VertexOutput vs20(const std::string& body, const ConstantBank& c) {
  return vs("vs_2_0", body, c);
}
inline VertexOutput vs11(const std::string& body, const ConstantBank& c) {
  return vs("vs_1_1", body, c);
}

// ps_2_0 harness: c0..c3 copied to r0..r3; the body must leave its result in r4, which
// is written to oC0.
inline Vec4 ps20(const std::string& body, const ConstantBank& c) {
  std::string text =
      "ps_2_0\nmov r0, c0\nmov r1, c1\nmov r2, c2\nmov r3, c3\n" + body + "mov oC0, r4\n";
  ShaderVM vm = vm_of(parse(text), {});
  static const ConstTextures none;
  return vm.run_pixel(PixelInput{}, c, none).color[0];
}

inline float nan_f() {
  return std::numeric_limits<float>::quiet_NaN();
}
inline float inf_f() {
  return std::numeric_limits<float>::infinity();
}

#define EXPECT_VEC4(v, a, b, c, d)                                                                 \
  do {                                                                                             \
    const auto vv_ = (v);                                                                          \
    EXPECT_FLOAT_EQ(vv_[0], (a));                                                                  \
    EXPECT_FLOAT_EQ(vv_[1], (b));                                                                  \
    EXPECT_FLOAT_EQ(vv_[2], (c));                                                                  \
    EXPECT_FLOAT_EQ(vv_[3], (d));                                                                  \
  } while (0)

} // namespace vmtest
