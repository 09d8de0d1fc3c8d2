// The GLSL front end (tierlift/glsl): the seed's shader through glslang to SPIR-V that passes
// spirv-val, with its sampler at tierlift's binding and its varying at location 0; bad GLSL
// as a positioned diagnostic naming the GLSL file. Expected positions are counted by hand in
// the texts below (columns 1-based).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tierlift/codegen/codegen.h"
#include "tierlift/glsl/glsl.h"
#include "tierlift/ir/result_diagnostics.h"

namespace tierlift::glsl {
namespace {

const std::filesystem::path kSeedH =
    std::filesystem::path(TIERLIFT_SOURCE_DIR) / "listings/glsl/seed004_blur_h.frag";

// The value of decoration `decoration` (Binding 33, Location 30) on any id, or -1.
std::vector<int64_t> decorations(const std::vector<uint32_t>& words, uint32_t decoration) {
  std::vector<int64_t> out;
  for (size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16, op = words[i] & 0xffff;
    if (count == 0) break;
    if (op == 71 /* OpDecorate */ && count >= 4 && words[i + 2] == decoration)
      out.push_back(words[i + 3]);
    i += count;
  }
  return out;
}

TEST(GlslCompile, SeedShaderBecomesValidSpirvWithTierliftsBindings) {
  CompileResult r = compile_fragment_file(kSeedH.string());
  ASSERT_TRUE(r) << r.message();
  const ir::Status valid = codegen::validate(r->spirv); // spirv-val, Vulkan 1.1
  EXPECT_TRUE(valid) << valid.message();
  ASSERT_EQ(r->samplers.size(), 1u);
  EXPECT_EQ(r->samplers[0].name, "RTScene");
  EXPECT_EQ(r->samplers[0].stage, 0u);
  EXPECT_EQ(decorations(r->spirv, 33), std::vector<int64_t>{2}); // s0 at binding 2
  // vTexCoord in and the colour out: both at location 0.
  EXPECT_EQ(decorations(r->spirv, 30), (std::vector<int64_t>{0, 0}));
}

TEST(GlslCompile, VersionLineOfALegacySourceIsAccepted) {
  CompileResult r = compile_fragment("#version 110\nuniform sampler2D a;\nuniform sampler2D b;\n"
                                     "varying vec2 uv;\n"
                                     "void main() { gl_FragColor = texture2D(a, uv) + "
                                     "texture2D(b, uv); }\n",
                                     "two.frag");
  ASSERT_TRUE(r) << r.message();
  ASSERT_EQ(r->samplers.size(), 2u);
  EXPECT_EQ(r->samplers[0].stage, 0u);
  EXPECT_EQ(r->samplers[1].stage, 1u);
}

TEST(GlslCompile, UndeclaredIdentifierIsPositionedInTheGlslFile) {
  // Line 3, "undefined_thing" starts at column 10 ("  sum += " is 9 characters).
  CompileResult r = compile_fragment("varying vec2 uv;\nvoid main() { vec4 sum = vec4(0.0);\n"
                                     "  sum += undefined_thing;\n  gl_FragColor = sum; }\n",
                                     "bad.frag");
  ASSERT_FALSE(r);
  EXPECT_FALSE(ir::failed_with(r, kIoRule));
  EXPECT_EQ(r.message().rfind("bad.frag:3:10: error: 'undefined_thing': undeclared identifier", 0),
            0u)
      << r.message();
  EXPECT_NE(r.message().find("  sum += undefined_thing;\n"), std::string::npos) << r.message();
  EXPECT_NE(r.message().find("         ^"), std::string::npos)
      << r.message(); // the caret under col 10
}

TEST(GlslCompile, SyntaxErrorNamesLineAndToken) {
  // Line 2 lacks its ';': glslang stops at the '}' of line 3, column 1.
  CompileResult r = compile_fragment("void main() {\n  gl_FragColor = vec4(1.0)\n}\n", "semi.frag");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.message().rfind("semi.frag:3:1: error: ", 0), 0u) << r.message();
}

TEST(GlslCompile, NonSamplerUniformIsRefusedAtItsDeclaration) {
  // glslang refuses a loose uniform for Vulkan at its declaration (line 2); it quotes no
  // token of the line, so the column is 1.
  CompileResult r = compile_fragment("varying vec2 uv;\nuniform float gain;\n"
                                     "void main() { gl_FragColor = vec4(gain); }\n",
                                     "gain.frag");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.message().rfind("gain.frag:2:1: error: 'non-opaque uniforms outside a block': not "
                              "allowed when using GLSL for Vulkan",
                              0),
            0u)
      << r.message();
}

TEST(GlslCompile, UniformBlockIsRefusedByName) {
  // A block passes glslang; a graph pass has no values for it, so tierlift refuses it at
  // the line declaring its member: "gain" on line 2, column 25 ("uniform Params { float " is
  // 24 characters).
  CompileResult r = compile_fragment("varying vec2 uv;\nuniform Params { float gain; };\n"
                                     "void main() { gl_FragColor = vec4(gain); }\n",
                                     "block.frag");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.message().rfind("block.frag:2:", 0), 0u) << r.message();
  EXPECT_NE(r.message().find("a GLSL pass takes sampler uniforms only"), std::string::npos)
      << r.message();
}

TEST(GlslCompile, MissingFileIsAnIoError) {
  CompileResult r = compile_fragment_file("/nonexistent/blur.frag");
  ASSERT_FALSE(r);
  EXPECT_TRUE(ir::failed_with(r, kIoRule));
  EXPECT_EQ(r.message().rfind("/nonexistent/blur.frag: error: ", 0), 0u) << r.message();
}

TEST(GlslCompile, PlainVulkanGlslForTheBenchmarkPeer) {
  std::vector<uint32_t> words = compile_vulkan_glsl(
      Stage::Fragment, "#version 450\nlayout(location = 0) out vec4 c;\nvoid main() { c = "
                       "vec4(1.0); }\n");
  ASSERT_FALSE(words.empty());
  const ir::Status valid = codegen::validate(words);
  EXPECT_TRUE(valid) << valid.message();
  std::string log;
  EXPECT_TRUE(
      compile_vulkan_glsl(Stage::Fragment, "#version 450\nvoid main() { x; }\n", &log).empty());
  EXPECT_NE(log.find("undeclared identifier"), std::string::npos) << log;
}

} // namespace
} // namespace tierlift::glsl
