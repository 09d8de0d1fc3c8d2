// The C-style preprocessor: macros, conditionals, #include, -D, and positions through it.
#include <filesystem>
#include <fstream>

#include "temp_dir.h"
#include "test_util.h"

namespace tierlift::assembly::test {
namespace {

namespace fs = std::filesystem;

TEST(Preprocessor, ObjectLikeMacroKeepsThePositionOfItsUse) {
  ir::Program p = must_parse("#define POS oPos\n#define SRC v0\nvs_1_1\nmov  POS, SRC\n");
  ASSERT_EQ(p.code.size(), 1u);
  EXPECT_EQ(p.code[0].dst->file, ir::RegFile::RastOut);
  EXPECT_EQ(p.code[0].dst->loc.line, 4u);
  EXPECT_EQ(p.code[0].dst->loc.col, 6u);
  EXPECT_EQ(p.code[0].src[0].loc.col, 11u);
}

TEST(Preprocessor, FunctionLikeMacroAndNesting) {
  ir::Program p =
      must_parse("vs_1_1\n#define XFORM(dst, src, m) m4x4 dst, src, m\n#define WORLD c4\n"
                 "#define TWICE(x) add x, x, x\nXFORM(oPos, v0, WORLD)\nTWICE(r1)\n");
  ASSERT_EQ(p.code.size(), 2u);
  EXPECT_EQ(p.code[0].op, ir::Opcode::M4x4);
  EXPECT_EQ(p.code[0].src[1].index, 4u);
  EXPECT_EQ(p.code[0].loc.line, 5u);
  EXPECT_EQ(p.code[0].loc.col, 1u);
  EXPECT_EQ(p.code[1].op, ir::Opcode::Add);
  EXPECT_EQ(p.code[1].src[1].index, 1u);
}

TEST(Preprocessor, TokenPasting) {
  ir::Program p = must_parse("vs_1_1\n#define OUT(n) oT##n\n#define REG(f, n) f ## n\n#define N 3\n"
                             "mov OUT(2), REG(v, 1)\nmov REG(r, 11), v0\n");
  ASSERT_EQ(p.code.size(), 2u);
  EXPECT_EQ(p.code[1].dst->file, ir::RegFile::Temp);
  EXPECT_EQ(p.code[1].dst->index, 11u);
  EXPECT_EQ(p.code[0].dst->file, ir::RegFile::TexCrdOut);
  EXPECT_EQ(p.code[0].dst->index, 2u);
  EXPECT_EQ(p.code[0].src[0].file, ir::RegFile::Input);
  EXPECT_EQ(p.code[0].src[0].index, 1u);
  // Next to ## the argument is not expanded first (C rule): oT##N gives oTN.
  auto e = first_error("vs_1_1\n#define OUT(n) oT##n\n#define N 3\nmov OUT(N), v0\n");
  EXPECT_EQ(e.rule, "unknown-register");
}

TEST(Preprocessor, SelfReferenceDoesNotLoopAndUndefWorks) {
  ir::Program p =
      must_parse("vs_1_1\n#define r0 r0\n#define A B\n#define B A\nmov r0, v0\n#undef r0\n"
                 "#define v0 v1\nmov r1, v0\n#undef v0\nmov r2, v0\n");
  ASSERT_EQ(p.code.size(), 3u);
  EXPECT_EQ(p.code[1].src[0].index, 1u);
  EXPECT_EQ(p.code[2].src[0].index, 0u);
  // A → B → A stops; 'A' is no register.
  expect_first_errors({{.text = "vs_1_1\n#define A B\n#define B A\nmov A, v0\n",
                        .rule = "unknown-register",
                        .line = 4,
                        .col = 5}});
}

TEST(Preprocessor, ConditionalsWithExpressions) {
  ir::Program p = must_parse(
      "vs_1_1\n#define LEVEL 2\n"
      "#if LEVEL > 1 && defined(LEVEL)\nmov r0, c0\n#elif 1\nmov r0, c1\n#else\nmov r0, "
      "c2\n#endif\n"
      "#if (LEVEL * 3 - 6) || !defined LEVEL\nmov r1, c0\n#elif LEVEL == 2\nmov r1, c1\n#else\n"
      "mov r1, c2\n#endif\n"
      "#ifdef NOPE\nmov r2, c0\n#if 1\nnested\n#endif\n#else\nmov r2, c2\n#endif\n"
      "#ifndef NOPE\nmov r3, c3\n#endif\n"
      "#if 0\n#error not reached\ngarbage here\n#endif\n"
      "#if 0x10 == 16 && (7 % 4) == 3 && (1 << 4) == 16 && -1 < 0 && (2 ? 5 : 6) == 5\n"
      "mov r4, c4\n#endif\n");
  ASSERT_EQ(p.code.size(), 5u);
  EXPECT_EQ(p.code[0].src[0].index, 0u);
  EXPECT_EQ(p.code[1].src[0].index, 1u);
  EXPECT_EQ(p.code[2].src[0].index, 2u);
  EXPECT_EQ(p.code[3].src[0].index, 3u);
  EXPECT_EQ(p.code[4].src[0].index, 4u);
}

TEST(Preprocessor, CommandLineDefines) {
  ParseOptions opts;
  opts.defines = {{"USE_FOG", ""}, {"BASE", "c8"}};
  ir::Program p = must_parse(
      "vs_1_1\n#ifdef USE_FOG\nmov oFog, v0.x\n#endif\n#if USE_FOG == 1\nm4x4 oPos, v0, BASE\n"
      "#endif\n",
      opts);
  ASSERT_EQ(p.code.size(), 2u);
  EXPECT_EQ(p.code[1].src[1].index, 8u);
}

TEST(Preprocessor, ErrorsAndUnterminatedIf) {
  expect_first_errors({
      {.text = "vs_1_1\n#error stop here\nmov r0, v0\n",
       .rule = "preprocessor",
       .line = 2,
       .col = 1,
       .message_has = "stop here"},
      {.text = "vs_1_1\nmov r0, v0\n  #if 1\nmov r1, v0\n",
       .rule = "preprocessor",
       .line = 3,
       .col = 3},
      {.text = "vs_1_1\n#if 1 / 0\n#endif\n", .rule = "preprocessor"},
      {.text = "vs_1_1\n#endif\n", .rule = "preprocessor"},
      {.text = "vs_1_1\n#define F(a, b) a b\nF(mov)\n", .rule = "preprocessor", .line = 3},
  });
}

TEST(Preprocessor, DeeplyNestedExpressionsAndMacrosAreBounded) {
  std::string chain = "vs_1_1\n";
  for (int i = 0; i < 200; ++i)
    chain += "#define M" + std::to_string(i) + " M" + std::to_string(i + 1) + "\n";
  chain += "mov r0, M0\n";
  expect_first_errors({
      {.text = "vs_1_1\n#if " + std::string(100000, '(') + "1\n#endif\n", .rule = "preprocessor"},
      {.text = "vs_1_1\n#if " + std::string(100000, '-') + "1\n#endif\n", .rule = "preprocessor"},
      {.text = chain, .rule = "preprocessor", .line = 202}, // 64 levels of expansion at most
  });
}

TEST(Preprocessor, ExponentialMacrosAreCutOff) {
  std::string text = "vs_1_1\n#define M0 r0\n";
  for (int i = 1; i <= 40; ++i)
    text += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + " M" +
            std::to_string(i - 1) + "\n";
  text += "M40\n";
  auto e = first_error(text);
  EXPECT_EQ(e.rule, "preprocessor");
}

class PreprocessorInclude : public ::testing::Test {
protected:
  void SetUp() override { fs::create_directories(dir_ / "inc"); }
  void write(const fs::path& rel, const std::string& text) {
    std::ofstream(dir_ / rel, std::ios::binary) << text;
  }
  ParseResult parse_file(const fs::path& rel, const ParseOptions& opts = {}) {
    std::ifstream in(dir_ / rel, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return parse_text(text, (dir_ / rel).string(), opts);
  }
  tierlift::test::TempDir tmp_{"pp"};
  const fs::path dir_ = tmp_.path();
};

TEST_F(PreprocessorInclude, RelativeToTheIncludingFileThenIncludeDirs) {
  write("main.vsh", "vs_1_1\n#include \"common.inc\"\n#include <lib.inc>\nmov oPos, POSITION\n");
  write("common.inc", "#define POSITION v0\n");
  write("inc/lib.inc", "\n  mov oD0, v1\n");
  ParseOptions opts;
  opts.include_dirs = {(dir_ / "inc").string()};
  ParseResult r = parse_file("main.vsh", opts);
  ASSERT_TRUE(r.program) << ir::render_text(r.diags, r.sources);
  ASSERT_EQ(r.program->code.size(), 2u);
  const ir::Instruction& from_lib = r.program->code[0];
  EXPECT_EQ(from_lib.dst->file, ir::RegFile::AttrOut);
  ASSERT_LT(from_lib.loc.file, r.sources.files.size());
  EXPECT_NE(r.sources.files[from_lib.loc.file].name.find("lib.inc"), std::string::npos);
  EXPECT_EQ(from_lib.loc.line, 2u);
  EXPECT_EQ(from_lib.loc.col, 3u);
  EXPECT_EQ(r.sources.files.size(), 3u); // main, common.inc, lib.inc
}

TEST_F(PreprocessorInclude, ErrorsInsideAnIncludedFilePointIntoIt) {
  write("main.vsh", "vs_1_1\n#include \"bad.inc\"\n");
  write("bad.inc", "mov r0, v0\nmov r0, zz\n");
  ParseResult r = parse_file("main.vsh");
  ASSERT_FALSE(r.program);
  const auto& d = r.diags.all().front();
  EXPECT_EQ(d.rule, "unknown-register");
  EXPECT_NE(r.sources.files[d.loc.file].name.find("bad.inc"), std::string::npos);
  EXPECT_EQ(d.loc.line, 2u);
  EXPECT_EQ(d.loc.col, 9u);
}

TEST_F(PreprocessorInclude, CanBeDisabled) {
  write("main.vsh", "vs_1_1\n#include \"common.inc\"\n");
  write("common.inc", "mov oPos, v0\n");
  ParseOptions opts;
  opts.allow_include = false;
  ParseResult r = parse_file("main.vsh", opts);
  ASSERT_FALSE(r.program);
  EXPECT_EQ(r.diags.all().front().rule, "preprocessor");
  EXPECT_EQ(r.diags.all().front().loc.line, 2u);
  EXPECT_EQ(r.sources.files.size(), 1u);
}

TEST_F(PreprocessorInclude, CyclesMissingFilesAndDepth) {
  write("a.inc", "#include \"b.inc\"\n");
  write("b.inc", "#include \"a.inc\"\n");
  write("main.vsh", "vs_1_1\n#include \"a.inc\"\n");
  ParseResult r = parse_file("main.vsh");
  ASSERT_FALSE(r.program);
  EXPECT_NE(r.diags.all().front().message.find("cycle"), std::string::npos)
      << r.diags.all().front().message;

  write("self.vsh", "vs_1_1\n#include \"self.vsh\"\n");
  EXPECT_FALSE(parse_file("self.vsh").program);

  write("missing.vsh", "vs_1_1\n#include \"nowhere.inc\"\n");
  ParseResult m = parse_file("missing.vsh");
  ASSERT_FALSE(m.program);
  EXPECT_EQ(m.diags.all().front().rule, "preprocessor");
  EXPECT_EQ(m.diags.all().front().loc.line, 2u);

  // A chain of 40 distinct files: deeper than 32 levels.
  for (int i = 0; i < 40; ++i)
    write("d" + std::to_string(i) + ".inc", "#include \"d" + std::to_string(i + 1) + ".inc\"\n");
  write("d40.inc", "mov r0, v0\n");
  write("deep.vsh", "vs_1_1\n#include \"d0.inc\"\n");
  ParseResult deep = parse_file("deep.vsh");
  ASSERT_FALSE(deep.program);
  EXPECT_NE(deep.diags.all().front().message.find("deeper"), std::string::npos);
}

} // namespace
} // namespace tierlift::assembly::test
