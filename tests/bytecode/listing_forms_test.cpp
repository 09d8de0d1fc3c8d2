// Every listing we hold, read as text and as its token stream, loads to the same program:
// the devices only ever see the program, so `run --ps x.pso` and `run --ps x.psh` draw the
// same image on both devices. The stream is the assembler's (checked against hand-derived
// tokens in roundtrip_listing_test.cpp and windows_assembler_test.cpp).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/load.h"

#include "listing_files.h"
#include "skip_policy.h"
#include "tierlift/ir/result_diagnostics.h"

namespace fs = std::filesystem;
using namespace tierlift;

namespace {

std::optional<ir::Program> load(std::string bytes, const std::string& name,
                                assembly::ListingForm expect_form, std::string& rendered) {
  ir::SourceManager sm;
  uint32_t f = sm.add(name, std::move(bytes));
  assembly::Loaded r = assembly::load_listing(f, sm);
  rendered = ir::render_text(r.program.diagnostics(), sm);
  EXPECT_EQ(r.form, expect_form) << name;
  if (!r.program) return std::nullopt;
  return std::move(r.program).value();
}

// Returns the number of listings compared.
size_t compare_forms(const std::vector<fs::path>& files) {
  size_t n = 0;
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    std::string why;
    auto text = load(test::read_file(file), file.string(), assembly::ListingForm::Text, why);
    if (!text) continue; // a listing that is invalid as text is not ours to compare
    auto tokens = assembly::assemble(*text);
    auto raw = load(assembly::tokens_to_bytes(tokens), file.string() + ".bin",
                    assembly::ListingForm::TokenStream, why);
    EXPECT_TRUE(raw.has_value()) << why;
    if (!raw) continue;
    EXPECT_TRUE(ir::same_ir(*text, *raw)) << ir::ir_difference(*text, *raw);
    std::string c_array = "const DWORD g[] = {";
    for (uint32_t t : tokens) c_array += fmt::format(" 0x{:08x},", t);
    c_array += " };\n";
    auto arr = load(c_array, file.string() + ".h", assembly::ListingForm::TokenArray, why);
    EXPECT_TRUE(arr.has_value()) << why;
    if (!arr) continue;
    EXPECT_TRUE(ir::same_ir(*text, *arr)) << ir::ir_difference(*text, *arr);
    ++n;
  }
  return n;
}

} // namespace

TEST(ListingForms, OurListingsLoadTheSameFromTokens) {
  auto files = test::listings_in(fs::path(TIERLIFT_SOURCE_DIR) / "listings", true);
  ASSERT_GE(files.size(), 13u);
  EXPECT_EQ(compare_forms(files), files.size());
}

TEST(ListingForms, SharedCorpusLoadsTheSameFromTokens) {
  auto files = test::listings_in(fs::path(TIERLIFT_SHARED_DIR) / "corpus");
  if (files.empty())
    TIERLIFT_SKIP_UNLESS_REQUIRED(test::kRequireCorpus,
                                  "no shared corpus (TIERLIFT_SHARED_DIR/corpus)");
  EXPECT_GT(compare_forms(files), 0u);
}
