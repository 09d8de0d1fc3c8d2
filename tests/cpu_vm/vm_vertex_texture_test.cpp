// Vertex texture fetch on the interpreter (NUMERICS.md F14): a vs_3_0's texldl reads the
// texture unit run_vertex is given, at the sampler the listing names and with the lod src.w
// as an explicit level of detail (a vertex has no neighbours to take gradients from).
#include "vm_test_util.h"

using namespace vmtest;

namespace {

// Records what the read asked for and answers a value that names the stage.
class RecordingTextures final : public TextureUnit {
public:
  mutable int stage = -1;
  mutable Vec4 coord{};
  mutable tierlift::pass::LodInput lod{};
  mutable int reads = 0;
  Vec4 sample(uint32_t, const Vec4&, float) const override {
    ADD_FAILURE() << "texldl must read by lod (sample_lod), not sample()";
    return {};
  }
  Vec4 sample_lod(uint32_t s, const Vec4& c, const tierlift::pass::LodInput& in) const override {
    stage = static_cast<int>(s);
    coord = c;
    lod = in;
    ++reads;
    return {10.0f * static_cast<float>(s), 0.5f, -2.0f, 7.0f};
  }
};

const char* const kVs = "vs_3_0\n"
                        "dcl_position v0\n"
                        "dcl_2d s2\n"
                        "dcl_position o0\n"
                        "dcl_texcoord0 o1\n"
                        "mov o0, v0\n"
                        "texldl r0, c0, s2\n"
                        "mov o1, r0\n";

TEST(VmVertexTexture, TexldlReadsTheVertexSamplerAtTheLodItGives) {
  const ShaderVM vm = make_vm(kVs, {});
  const ConstantBank c = bank({{0.25f, 0.75f, 0.5f, 3.5f}});
  RecordingTextures tex;
  const VertexOutput o = vm.run_vertex(VertexInput{}, c, tex);
  EXPECT_EQ(tex.reads, 1);
  EXPECT_EQ(tex.stage, 2); // the listing's s2: the vertex stage's sampler 2
  EXPECT_VEC4(tex.coord, 0.25f, 0.75f, 0.5f, 3.5f);
  EXPECT_TRUE(tex.lod.explicit_lod);
  EXPECT_EQ(tex.lod.lod, 3.5f); // src.w, no bias
  EXPECT_FALSE(tex.lod.has_bias);
  EXPECT_VEC4(o.tex[0], 20.0f, 0.5f, -2.0f, 7.0f);
  EXPECT_EQ(o.tex_written, 1u);
}

TEST(VmVertexTexture, WithoutSamplersTexldlReadsOpaqueBlack) {
  // run_vertex without a texture unit: every sampler is unbound, (0, 0, 0, 1) as in D3D9.
  const ShaderVM vm = make_vm(kVs, {});
  const VertexOutput o = run_vs(vm, VertexInput{}, bank({{0.25f, 0.75f, 0, 0}}));
  EXPECT_VEC4(o.tex[0], 0, 0, 0, 1);
}

} // namespace
