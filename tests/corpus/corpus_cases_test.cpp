// The corpus library's discovery, stages and reports (tierlift/corpus).
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

#include "skip_policy.h"
#include "tierlift/corpus/cases.h"
#include "tierlift/corpus/report.h"
#include "tierlift/corpus/stages.h"
#include "tierlift/vulkan/process_device.h"

namespace fs = std::filesystem;
using namespace tierlift::corpus;

namespace {

fs::path fresh_dir(const std::string& name) {
  fs::path d =
      fs::temp_directory_path() / ("tierlift_corpus_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& bytes) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
}

const std::string kPs = "ps_2_0\ndcl t0\nmov r0, t0\nmov oC0, r0\n";

} // namespace

TEST(CorpusIds, Fnv1aOfKnownStrings) {
  // Published FNV-1a 64 test vectors.
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(case_id("x/a.psh", "a"), "x/a.psh@af63dc4c8601ec8c");
}

// A text file is a listing when a line starts (after blanks) with a version: vs or ps, '.'
// or '_', a digit, '.' or '_', and a digit, x, s or w, in any case.
TEST(CorpusDiscovery, TextIsAListingWhenALineStartsWithAVersion) {
  for (const char* yes : {"ps_2_0\n", "  \tvs.1.1\nmov oPos, v0", "PS_3_SW",
                          "; a comment\nps_2_x\n", "\nvs_1_1", "// c\r\n  Ps.1.4\r\n", "vs_3_0"})
    EXPECT_TRUE(looks_like_listing(yes)) << yes;
  for (const char* no : {"", "# README\nuse ps_2_0 here\n", "ps_2", "xps_2_0", "vs_3_q", "ps-2-0",
                         "ps_a_0", "vx_1_1", "p s_2_0", "(ps_2_0)"})
    EXPECT_FALSE(looks_like_listing(no)) << no;
}

TEST(CorpusDiscovery, FolderKeepsListingsOnlyWithIdsRelativeToTheRoot) {
  fs::path root = fresh_dir("folder") / "shaders";
  write(root / "sub" / "a.psh", kPs);
  write(root / "README.md", "# notes\nnothing to see\n");
  write(root / "include" / "frag.inc", "mov r0, c0\n"); // no version line: a fragment
  write(root / ".hidden" / "b.psh", kPs);
  write(root / "t.bin", std::string("\x00\x02\xff\xff\xff\xff\x00\x00", 8));
  auto found = discover({root.string() + "/"});
  ASSERT_TRUE(found) << found.message();
  ASSERT_EQ(found->size(), 2u);
  EXPECT_EQ((*found)[0].id, case_id("shaders/sub/a.psh", kPs));
  EXPECT_EQ((*found)[1].id.substr(0, 14), "shaders/t.bin@");
}

TEST(CorpusDiscovery, ListFileNamesFilesAndMissingRootIsAnError) {
  fs::path dir = fresh_dir("list");
  write(dir / "a.psh", kPs);
  write(dir / "b.vsh", "vs_1_1\ndcl_position v0\nmov oPos, v0\n");
  write(dir / "corpus.txt", "# two shaders\na.psh\n\nb.vsh\n");
  auto found = discover({(dir / "corpus.txt").string()});
  ASSERT_TRUE(found) << found.message();
  ASSERT_EQ(found->size(), 2u);
  EXPECT_EQ((*found)[0].id.substr(0, 6), "a.psh@");
  EXPECT_EQ((*found)[1].id.substr(0, 6), "b.vsh@");
  EXPECT_FALSE(discover({(dir / "nope").string()}));
}

TEST(CorpusShard, SharesPartitionTheCases) {
  std::vector<size_t> per(3, 0);
  for (int i = 0; i < 300; ++i) {
    Case c;
    c.id = "case" + std::to_string(i);
    int owners = 0;
    for (size_t s = 0; s < 3; ++s)
      if (in_shard(c, s, 3)) ++owners, ++per[s];
    EXPECT_EQ(owners, 1);
  }
  for (size_t n : per) EXPECT_GT(n, 50u); // a hash, not one shard taking everything
}

namespace {
StageOptions no_device() {
  StageOptions o;
  o.device = nullptr;
  return o;
}
Verdict stage_verdict(const CaseResult& r, std::string_view stage) {
  for (const StageResult& s : r.stages)
    if (s.stage == stage) return s.verdict;
  return Verdict::Crash; // absent: never a stage's verdict
}
} // namespace

TEST(CorpusStages, ValidTextPassesEveryStageBeforeTheDraw) {
  CaseResult r = run_listing("a", "a.psh", kPs, no_device());
  EXPECT_EQ(r.profile, "ps_2_0");
  EXPECT_EQ(stage_verdict(r, kStageParse), Verdict::Pass);
  EXPECT_EQ(stage_verdict(r, kStageValidate), Verdict::Pass);
  EXPECT_EQ(stage_verdict(r, kStageRoundTrip), Verdict::Pass);
  EXPECT_EQ(stage_verdict(r, kStageSpirv), Verdict::Pass);
  EXPECT_EQ(stage_verdict(r, kStageDiff), Verdict::Skip); // no device given
  EXPECT_EQ(r.verdict, Verdict::Pass);
}

TEST(CorpusStages, InvalidListingFailsValidateAndSkipsTheRest) {
  // r1 read before it is written: parses, does not validate.
  CaseResult r = run_listing("b", "b.psh", "ps_2_0\nmov oC0, r1\n", no_device());
  EXPECT_EQ(stage_verdict(r, kStageParse), Verdict::Pass);
  EXPECT_EQ(stage_verdict(r, kStageValidate), Verdict::Fail);
  EXPECT_EQ(stage_verdict(r, kStageSpirv), Verdict::Skip);
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_EQ(r.failed_stage(), "validate");
}

TEST(CorpusStages, ShaderModel3RunsAndARelativeOutputWriteToo) {
  // The front end takes all three; SPIR-V runs the first, the v0[aL] read of the second and
  // the o[aL] write of the third (NUMERICS.md F13); with a device the third's differential
  // run agrees.
  CaseResult r = run_listing("c", "c.psh", "ps_3_0\nmov oC0, c0\n", no_device());
  EXPECT_EQ(stage_verdict(r, kStageParse), Verdict::Pass);
  EXPECT_EQ(stage_verdict(r, kStageValidate), Verdict::Pass);
  EXPECT_EQ(stage_verdict(r, kStageRoundTrip), Verdict::Pass);
  EXPECT_EQ(stage_verdict(r, kStageSpirv), Verdict::Pass);
  CaseResult g = run_listing("g", "g.psh",
                             "ps_3_0\ndcl_texcoord0 v0\ndcl_texcoord1 v1\ndefi i0, 2, 0, 1, 0\n"
                             "mov r0, c0\nloop aL, i0\nadd r0, r0, v0[aL]\nendloop\nmov oC0, r0\n",
                             no_device());
  EXPECT_EQ(stage_verdict(g, kStageValidate), Verdict::Pass);
  EXPECT_EQ(stage_verdict(g, kStageSpirv), Verdict::Pass);
  const std::string h_text = "vs_3_0\ndcl_position v0\ndcl_position o0\ndcl_texcoord0 o1\n"
                             "defi i0, 1, 1, 1, 0\nmov o0, v0\nloop aL, i0\nmov o[aL], v0\n"
                             "endloop\n";
  CaseResult h = run_listing("h", "h.vsh", h_text, no_device());
  EXPECT_EQ(stage_verdict(h, kStageValidate), Verdict::Pass);
  EXPECT_EQ(stage_verdict(h, kStageSpirv), Verdict::Pass) << h.stages.back().message;
  EXPECT_EQ(h.verdict, Verdict::Pass);
  tierlift::ir::Result<tierlift::vulkan::Device*> device = tierlift::vulkan::process_device({});
  if (!device) TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device");
  StageOptions o;
  o.device = *device;
  const CaseResult d = run_listing("h", "h.vsh", h_text, o);
  ASSERT_EQ(d.stages.back().stage, kStageDiff);
  EXPECT_EQ(d.stages.back().verdict, Verdict::Pass) << d.stages.back().message;
}

TEST(CorpusStages, ShaderModel4IsUnsupportedNotAFailure) {
  CaseResult r = run_listing("d", "d.psh", "ps_4_0\nmov oC0, c0\n", no_device());
  EXPECT_EQ(stage_verdict(r, kStageParse), Verdict::Unsupported);
  EXPECT_EQ(r.verdict, Verdict::Unsupported);
  EXPECT_FALSE(r.stages.front().message.empty());
}

TEST(CorpusStages, TruncatedTokenStreamFailsParse) {
  // ps_2_0 version token, then half a mov instruction and no end token.
  const std::string bytes("\x00\x02\xff\xff\x01\x00\x00\x02", 8);
  CaseResult r = run_listing("d", "d.pso", bytes, no_device());
  EXPECT_EQ(stage_verdict(r, kStageParse), Verdict::Fail);
  EXPECT_EQ(r.verdict, Verdict::Fail);
}

TEST(CorpusStages, TokenStreamRoundTripsToTheSameTokens) {
  // ps_2_0; mov oC0, c0; end — assembled by hand (docs/d3d9-rules.md §11): opcode 1 with
  // its length 2 in bits 24-27; oC0 = type 8 (bits 28-30: 0, bits 11-12: 1), mask .xyzw;
  // c0 = type 2, swizzle .xyzw (0xE4 << 16).
  const uint32_t tokens[] = {0xFFFF0200u, 0x02000001u, 0x800F0800u, 0xA0E40000u, 0x0000FFFFu};
  std::string bytes(reinterpret_cast<const char*>(tokens), sizeof tokens);
  CaseResult r = run_listing("e", "e.pso", bytes, no_device());
  EXPECT_EQ(r.form, "D3D9 token stream");
  EXPECT_EQ(stage_verdict(r, kStageParse), Verdict::Pass) << r.stages.front().message;
  EXPECT_EQ(stage_verdict(r, kStageRoundTrip), Verdict::Pass) << r.stages[2].message;
}

TEST(CorpusStages, CheckOnlyStopsAfterValidation) {
  StageOptions o = no_device();
  o.check_only = true;
  CaseResult r = run_listing("f", "f.psh", kPs, o);
  EXPECT_EQ(stage_verdict(r, kStageValidate), Verdict::Pass);
  EXPECT_EQ(stage_verdict(r, kStageRoundTrip), Verdict::Skip);
  EXPECT_EQ(stage_verdict(r, kStageSpirv), Verdict::Skip);
}
