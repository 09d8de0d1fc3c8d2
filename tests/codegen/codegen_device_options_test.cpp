// The options the Vulkan device sets per draw from what it binds.
// * stage_fetch_unorm8: a point read of an RGBA8 texture becomes a texel fetch plus a few
//   float operations that turn the device's UNORM value into k/255.0f exactly. The module
//   must validate and use the fetch only where asked (2D stages); the arithmetic the shader
//   does is replayed here on the host, for every level and for device values up to two ulps
//   away from k/255 (lavapipe's are one ulp off for 126 levels).
// * known_*_constants: a constant whose components hold the same bits is read as one float,
//   replicated; a product with a constant never zero tests only the other factor for zero
//   (the Vulkan tests compare the images with the interpreter's).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "compile_valid.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/codegen/codegen.h"

using namespace tierlift;

namespace {

std::optional<codegen::ShaderModule> build(const std::string& text,
                                           const codegen::CodegenOptions& opt) {
  auto parsed = assembly::parse_text(text, "<test>");
  EXPECT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  if (!parsed.program) return std::nullopt;
  return test::compile_valid(*parsed.program, parsed.sources, opt);
}

std::string dis(const codegen::ShaderModule& m) {
  ir::Result<std::string> text = codegen::disassemble(m.words);
  EXPECT_TRUE(text) << text.message();
  return text ? *text : std::string();
}

constexpr const char* kTwoStages = "ps_2_0\ndcl t0.xy\ndcl t1.xyz\ndcl_2d s0\ndcl_cube s1\n"
                                   "texld r0, t0, s0\ntexld r1, t1, s1\nadd oC0, r0, r1\n";

TEST(CodegenFetchUnorm8, TwoDStagesFetchAndOthersStillSample) {
  codegen::CodegenOptions opt;
  opt.stage_fetch_unorm8[0] = opt.stage_fetch_unorm8[1] = true;
  const auto m = build(kTwoStages, opt);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->samplers.size(), 2u);
  for (const codegen::SamplerInfo& s : m->samplers)
    EXPECT_EQ(s.fetch_unorm8, s.stage == 0) << "s" << s.stage; // a cube map is sampled
  const std::string text = dis(*m);
  EXPECT_NE(text.find("OpImageFetch"), std::string::npos);
  EXPECT_NE(text.find("OpImageQuerySizeLod"), std::string::npos);
  EXPECT_NE(text.find("OpImageSampleImplicitLod"), std::string::npos); // s1

  const auto plain = build(kTwoStages, {});
  ASSERT_TRUE(plain);
  for (const codegen::SamplerInfo& s : plain->samplers) EXPECT_FALSE(s.fetch_unorm8);
  EXPECT_EQ(dis(*plain).find("OpImageFetch"), std::string::npos);
}

TEST(CodegenFetchUnorm8, Ps1xTexFetchesToo) {
  codegen::CodegenOptions opt;
  opt.stage_fetch_unorm8[2] = true;
  const auto m = build("ps_1_1\ntex t2\nmov r0, t2\n", opt);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->samplers.size(), 1u);
  EXPECT_TRUE(m->samplers[0].fetch_unorm8);
}

// CodegenOptions::point_sampling_floors (lavapipe): the device's own point sampler finds the
// texel at the coordinate clamped to [0, 1]; the value is decoded the same way. The Vulkan
// tests compare both ways with the interpreter on lavapipe.
TEST(CodegenFetchUnorm8, PointSamplingFloorsSamplesTheClampedCoordinate) {
  codegen::CodegenOptions opt;
  opt.stage_fetch_unorm8[0] = true;
  opt.point_sampling_floors = true;
  const auto m = build(kTwoStages, opt);
  ASSERT_TRUE(m);
  EXPECT_TRUE(m->samplers[0].fetch_unorm8);
  const std::string text = dis(*m);
  EXPECT_EQ(text.find("OpImageFetch"), std::string::npos);
  EXPECT_EQ(text.find("OpImageQuerySizeLod"), std::string::npos);
  EXPECT_NE(text.find("NClamp"), std::string::npos);
  EXPECT_NE(text.find("RoundEven"), std::string::npos); // the decode
}

// The shader's steps on one value v (emit_texture.cpp), each rounded to float as the device
// rounds it: k = roundEven(v·255), then (k·65793 + v)·2^-24.
float decode(float v) {
  const volatile float scaled = v * 255.0f;
  const float k = std::nearbyint(scaled); // round to nearest even (the default mode)
  const volatile float high = k * 65793.0f;
  const volatile float sum = high + v;
  return sum * 0x1p-24f;
}

TEST(CodegenFetchUnorm8, DecodeGivesKOver255ForEveryLevelWithinTwoUlps) {
  const float step = 1.0f / 255.0f;
  int inexact_products = 0;
  for (int k = 0; k < 256; ++k) {
    const float exact = static_cast<float>(k) / 255.0f; // correctly rounded
    const volatile float product = static_cast<float>(k) * step;
    if (product != exact) ++inexact_products;
    for (float start : {exact, static_cast<float>(product)}) {
      float lo = start, hi = start;
      for (int ulps = 0; ulps <= 2; ++ulps) {
        EXPECT_EQ(decode(lo), exact) << "k " << k << ", " << ulps << " ulps below";
        EXPECT_EQ(decode(hi), exact) << "k " << k << ", " << ulps << " ulps above";
        lo = k == 0 ? 0.0f : std::nextafter(lo, 0.0f);
        hi = k == 0 ? 0.0f : std::nextafter(hi, 2.0f);
      }
    }
  }
  EXPECT_EQ(inexact_products, 126); // the levels a k·(1/255) conversion gets wrong
}

// CodegenOptions::known_ps_constants: a c# whose four components hold the same bits, read
// without relative addressing, loads one float (a Uniform float pointer into the block) and
// replicates it; the others, and every relative read, stay vec4 loads. The module validates
// either way.
TEST(CodegenReplicatedConstants, ListedRegistersLoadOneComponent) {
  const std::string text = "ps_2_0\ndcl t0.xy\nmul r0, t0, c1\nmad r0, r0, c2, c1\nmov oC0, r0\n";
  codegen::CodegenOptions opt;
  opt.known_ps_constants = {{{1, 2, 3, 4}, {5, 5, 5, 5}, {1, 2, 3, 4}}}; // c1 replicated
  const auto m = build(text, opt);
  ASSERT_TRUE(m);
  const std::string with = dis(*m);
  EXPECT_NE(with.find("%_ptr_Uniform_float"), std::string::npos);
  const auto plain = build(text, {});
  ASSERT_TRUE(plain);
  EXPECT_EQ(dis(*plain).find("%_ptr_Uniform_float"), std::string::npos);
  // The vertex stage's values are its own: pixel-stage values leave a vertex listing alone.
  const auto vs = build("vs_2_0\ndcl_position v0\nmul oPos, v0, c1\n", opt);
  ASSERT_TRUE(vs);
  EXPECT_EQ(dis(*vs).find("%_ptr_Uniform_float"), std::string::npos);
}

size_t count(const std::string& text, const std::string& what) {
  return test::count_occurrences(text, what);
}

TEST(CodegenNonzeroConstants, ProductsTestOnlyTheOtherFactor) {
  const std::string text = "ps_2_0\ndcl t0.xy\nmul r0, t0, -c1.yzxw\nmov oC0, r0\n";
  codegen::CodegenOptions opt;
  opt.known_ps_constants = {{{0, 0, 0, 0}, {1, 2, 3, 4}}}; // c1 never zero
  const auto with = build(text, opt);
  const auto plain = build(text, {});
  ASSERT_TRUE(with && plain);
  EXPECT_EQ(count(dis(*with), "OpFOrdEqual"), 1u);
  EXPECT_EQ(count(dis(*with), "OpLogicalOr"), 0u);
  EXPECT_EQ(count(dis(*plain), "OpFOrdEqual"), 2u);
  EXPECT_EQ(count(dis(*plain), "OpLogicalOr"), 1u);
  // A register not listed, and ps_1_x (its constants are clamped to [-1, 1] on read; the
  // clamp of a NaN may be a zero), keep both tests.
  opt.known_ps_constants = {{{1, 2, 3, 4}, {0, 0, 0, 0}}};
  const auto other = build(text, opt);
  ASSERT_TRUE(other);
  EXPECT_EQ(count(dis(*other), "OpLogicalOr"), 1u);
  opt.known_ps_constants = {{{1, 2, 3, 4}}};
  const auto ps14 = build("ps_1_4\nmul r0, r0, c0\n", opt);
  ASSERT_TRUE(ps14);
  EXPECT_GE(count(dis(*ps14), "OpLogicalOr"), 1u);
}

TEST(CodegenNonzeroConstants, SomeComponentsKnown) {
  // c1 = (s, s, s, 0), as the glow's composite weights: x, y, z are known, and after the
  // .yzxw swizzle the unknown one is still w. One vector compare for t0, one float compare
  // for the constant's w, and a bvec4 of three false and that compare.
  const std::string text = "ps_2_0\ndcl t0.xy\nmul r0, t0, c1.yzxw\nmov oC0, r0\n";
  codegen::CodegenOptions opt;
  opt.known_ps_constants = {{{0, 0, 0, 0}, {0.5f, 0.5f, 0.5f, 0}}};
  const auto m = build(text, opt);
  ASSERT_TRUE(m);
  const std::string with = dis(*m);
  EXPECT_EQ(count(with, "OpFOrdEqual %v4bool"), 1u);
  EXPECT_EQ(count(with, "OpFOrdEqual %bool"), 1u);
  EXPECT_EQ(count(with, "OpCompositeConstruct %v4bool %false %false %false"), 1u);
}

} // namespace
