// Every article listing and every real-world corpus listing validates without an error.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "skip_policy.h"
#include "validator_test_util.h"

#include "listing_files.h"

namespace fs = std::filesystem;
using namespace tierlift;

namespace {

using tierlift::test::read_file;

int check_folder(const fs::path& dir) {
  int n = 0;
  for (const fs::path& file : tierlift::test::listings_in(dir)) {
    SCOPED_TRACE(file.string());
    EXPECT_TRUE(vtest::is_clean(read_file(file)));
    ++n;
  }
  return n;
}

TEST(ValidatorCorpus, ArticleListingsValidate) {
  EXPECT_EQ(check_folder(fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "gpugems21"), 4);
}

TEST(ValidatorCorpus, SharedCorpusValidates) {
  fs::path dir = fs::path(TIERLIFT_SHARED_DIR) / "corpus";
  if (!fs::is_directory(dir))
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireCorpus, dir.string() + " is absent");
  EXPECT_EQ(check_folder(dir), 16);
}

// The article's dx8 pixel listing is exactly at the ps_1_3 texture limit (4 tex) and uses 4
// of its 8 arithmetic slots; as ps_1_1 it is still legal, as ps_1_4 `tex` does not exist.
TEST(ValidatorCorpus, Listing4AgainstOtherProfiles) {
  std::string text = read_file(fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "gpugems21" /
                               "listing4_blur4_weighted_sum.psh");
  vtest::Run r = vtest::run(text, ir::Profile::ps_1_1);
  EXPECT_FALSE(r.diags.has_errors()) << vtest::dump(r);
  EXPECT_TRUE(
      vtest::has_error(text, "not-in-profile", 2, 1, {"tex", "ps_1_4"}, ir::Profile::ps_1_4));
}

// Validating any listing against any profile reports, never crashes (run under ASan/UBSan
// in CI).
TEST(ValidatorCorpus, EveryListingAgainstEveryProfile) {
  std::vector<fs::path> files;
  for (const auto& e :
       fs::directory_iterator(fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "gpugems21"))
    files.push_back(e.path());
  fs::path dir = fs::path(TIERLIFT_SHARED_DIR) / "corpus";
  if (::tierlift::test::required(::tierlift::test::kRequireCorpus)) {
    ASSERT_TRUE(fs::is_directory(dir)) << dir << " is absent and TIERLIFT_REQUIRE_CORPUS is set";
  }
  if (fs::is_directory(dir)) {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() != ".md") files.push_back(e.path());
  }
  for (const fs::path& f : files) {
    for (ir::Profile p : ir::kAllProfiles) {
      vtest::Run r = vtest::run(read_file(f), p);
      ASSERT_TRUE(r.parsed.program) << f;
      bool same_stage = ir::stage_of(p) == r.parsed.program->stage();
      if (!same_stage) {
        EXPECT_FALSE(r.valid) << f << " as " << ir::profile_name(p);
      }
      for (const ir::Diagnostic& d : r.diags.all()) {
        EXPECT_FALSE(d.rule.empty());
        EXPECT_FALSE(d.message.empty());
      }
    }
  }
}

} // namespace
