// The generated corpus against a planted translation bug. The SPIR-V emitter has one
// test-only switch (TIERLIFT_TEST_PLANT=drop-negate, read in codegen/src/emit_operands.cpp)
// that drops the negation of every source modifier. Generated ps_2_0 listings, drawn by the
// interpreter and by Vulkan over the differential harness's inputs (diff_harness.h), must
//   * all agree without the plant,
//   * disagree with it within the first 50 listings,
// and the first disagreeing listing must reduce (gen::reduce_listing) to a few statements
// that still show the bug: valid, disagreeing with the plant, agreeing without it.
#include <cstdlib>
#include <regex>
#include <sstream>

#include "diff_harness.h"
#include "tierlift/generate/generate.h"

namespace tierlift::vulkan::test {
namespace {

// Every varying a generated ps_2_0 listing may read: t0..t3 and v0, v1, from the quad's
// corners and texture coordinates (kept in [0, 1], as colours must be).
const char* kQuadVs = "vs_2_0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\n"
                      "mov oT0, v3\nmov oT1, v3.yxzw\nmov oT2, v3.zwxy\nmov oT3, v3.wzyx\n"
                      "mov oD0, v3\nmov oD1, v3.yxwz\n";

constexpr std::size_t kListings = 50;

// Sets the plant for the life of the guard (tests in this file only).
class Plant {
public:
  Plant() { setenv("TIERLIFT_TEST_PLANT", "drop-negate", 1); }
  ~Plant() { unsetenv("TIERLIFT_TEST_PLANT"); }
  Plant(const Plant&) = delete;
  Plant& operator=(const Plant&) = delete;
};

gen::GenerateOptions harness_options() {
  gen::GenerateOptions o;
  o.only_2d_samplers = true; // the harness binds 2D textures
  o.extra_outputs = false;   // and one render target
  return o;
}

DiffSetup inputs() {
  DiffSetup s;
  s.seed = 1;
  add_random_textures(s, 4, {});
  s.ps_c = random_constants(100, 32, {});
  return s;
}

bool valid(const std::string& text) {
  assembly::ParseResult r = assembly::parse_text(text, "generated.psh");
  return r.program && assembly::validate(*r.program, r.diags);
}

// The first disagreement between the interpreter and Vulkan on `ps`, or "" when they agree.
std::string disagreement(vulkan::Device& dev, const std::string& ps) {
  DiffResult r = run_diff(dev, kQuadVs, ps, inputs());
  if (!r.ok) return "draw failed";
  if (r.diff.special_mismatch == 0 && r.diff.max_scaled <= 1e-5) return "";
  return r.diff.first_bad.empty() ? "differs" : r.diff.first_bad;
}

std::size_t statements(const std::string& text) {
  std::istringstream in(text);
  std::size_t n = 0;
  for (std::string l; std::getline(in, l);) n += !l.empty();
  return n;
}

using GeneratedPlant = VulkanTest;

TEST_F(GeneratedPlant, WithoutThePlantEveryGeneratedListingAgrees) {
  std::size_t agree = 0;
  for (std::size_t i = 0; i < kListings; ++i) {
    const std::string ps = gen::generate_listing("ps_2_0", 1, i, harness_options()).value();
    const std::string why = disagreement(*dev, ps);
    if (why.empty())
      ++agree;
    else
      ADD_FAILURE() << "listing " << i << ": " << why << "\n" << ps;
  }
  std::printf("[plant] without the plant: %zu of %zu generated ps_2_0 listings agree\n", agree,
              kListings);
  EXPECT_EQ(agree, kListings);
}

TEST_F(GeneratedPlant, ThePlantIsFoundAndReducedToAFewStatements) {
  std::optional<std::size_t> found;
  std::string ps, why;
  {
    Plant plant;
    for (std::size_t i = 0; i < kListings && !found; ++i) {
      ps = gen::generate_listing("ps_2_0", 1, i, harness_options()).value();
      why = disagreement(*dev, ps);
      if (!why.empty()) found = i;
    }
  }
  ASSERT_TRUE(found) << "the plant went unnoticed in " << kListings << " listings";
  std::printf("[plant] with the plant: listing %zu of seed 1 disagrees (%s), %zu statements\n",
              *found, why.c_str(), statements(ps));
  // The bug, not the listing: valid, wrong with the plant, right without it.
  std::size_t calls = 0;
  auto shows_the_bug = [&](const std::string& text) {
    ++calls;
    if (!valid(text)) return false;
    bool planted_differs = false;
    {
      Plant plant;
      planted_differs = !disagreement(*dev, text).empty();
    }
    return planted_differs && disagreement(*dev, text).empty();
  };
  ASSERT_TRUE(shows_the_bug(ps));
  const std::string reduced = gen::reduce_listing(ps, shows_the_bug);
  std::printf("[plant] reduced %zu -> %zu statements in %zu predicate calls:\n%s", statements(ps),
              statements(reduced), calls, reduced.c_str());
  EXPECT_TRUE(shows_the_bug(reduced));
  EXPECT_LE(statements(reduced), 5u) << reduced;
  // What is left carries a negation: the modifier the plant drops.
  EXPECT_TRUE(std::regex_search(reduced, std::regex(R"(, -)"))) << reduced;
}

} // namespace
} // namespace tierlift::vulkan::test
