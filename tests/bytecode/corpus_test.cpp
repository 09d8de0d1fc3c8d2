// tests/corpus: real shaders from open-source engines (tests/corpus/README.md says where each
// comes from and under which licence). Every file is taken; and where fxc wrote both the
// listing and its bytecode (a header of `#if 0` listing + `const BYTE g_*[]` array), our
// assembler gives fxc's bytes for the listing and reads fxc's bytes back to the same
// stream. fxc's streams start with a CTAB comment, which carries nothing an instruction
// needs: the listing (which has none) is compared with the stream without its comments, and
// the disassembly (which keeps them) with the whole stream.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "listing_files.h"
#include "loaded_listing.h"
#include "tierlift/assembly/bytecode.h"

namespace fs = std::filesystem;
using namespace tierlift;

namespace {

const fs::path kCorpus = fs::path(TIERLIFT_SOURCE_DIR) / "tests" / "corpus";

std::vector<fs::path> corpus_files() {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(kCorpus)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".vsh" || ext == ".psh" || ext == ".inc" || ext == ".c") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<uint32_t> without_comments(const std::vector<uint32_t>& tokens) {
  std::vector<uint32_t> out;
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (i > 0 && (tokens[i] & 0xFFFF) == 0xFFFE) {
      i += (tokens[i] >> 16) & 0x7FFF; // skip the payload
      continue;
    }
    out.push_back(tokens[i]);
  }
  return out;
}

std::string hex(const std::vector<uint32_t>& t) {
  std::string s;
  for (uint32_t v : t) s += fmt::format("{:08x} ", v);
  return s;
}

test::LoadedListing load(const fs::path& file) {
  assembly::LoadOptions options;
  options.parse.include_dirs.push_back(file.parent_path().string());
  return test::load_bytes(test::read_file(file), file.string(), options);
}

} // namespace

TEST(Corpus, EveryFileIsTaken) {
  size_t n = 0;
  for (const fs::path& file : corpus_files()) {
    SCOPED_TRACE(file.string());
    test::LoadedListing l = load(file);
    EXPECT_TRUE(l.r().program.ok()) << l.rendered;
    ++n;
  }
  EXPECT_GE(n, 41u);
}

// fxc's listing assembles to fxc's bytecode, and the bytecode reads back to itself.
TEST(Corpus, FxcListingsAssembleToFxcBytes) {
  size_t pairs = 0;
  for (const fs::path& header : corpus_files()) {
    if (header.extension() != ".inc") continue;
    fs::path text = header;
    text.replace_extension(".vsh");
    if (!fs::exists(text)) text.replace_extension(".psh");
    if (!fs::exists(text)) continue;
    SCOPED_TRACE(header.string());
    test::LoadedListing bytes = load(header);
    test::LoadedListing listing = load(text);
    ASSERT_EQ(bytes.r().form, assembly::ListingForm::TokenArray) << bytes.rendered;
    ASSERT_TRUE(bytes.r().program.ok()) << bytes.rendered;
    ASSERT_TRUE(listing.r().program.ok()) << listing.rendered;
    const std::vector<uint32_t> fxc = without_comments(bytes.r().tokens);
    EXPECT_EQ(hex(assembly::assemble(*listing.r().program)), hex(fxc));
    EXPECT_EQ(hex(assembly::assemble(*bytes.r().program)), hex(bytes.r().tokens));
    ++pairs;
  }
  EXPECT_EQ(pairs, 19u); // 16 librw headers, 3 SDL headers
}

// SDL keeps three ps_2_0 shaders as DWORD arrays in one C file: the first is read, and a
// note says so (it holds dp2add, 0x0400005A, as fxc wrote it).
TEST(Corpus, SdlSourceWithThreeArrays) {
  test::LoadedListing l = load(kCorpus / "sdl" / "SDL_shaders_d3d.c");
  ASSERT_TRUE(l.r().program.ok()) << l.rendered;
  EXPECT_EQ(l.r().form, assembly::ListingForm::TokenArray);
  EXPECT_NE(l.rendered.find("3 arrays"), std::string::npos) << l.rendered;
  EXPECT_NE(l.rendered.find("'D3D9_PixelShader_YUV_JPEG'"), std::string::npos) << l.rendered;
  const std::vector<uint32_t> tokens = without_comments(l.r().tokens);
  EXPECT_NE(std::find(tokens.begin(), tokens.end(), 0x0400005Au), tokens.end());
  EXPECT_EQ(hex(assembly::assemble(*l.r().program)), hex(l.r().tokens));
}
