// Robustness: thousands of deterministic mutations of real listings never crash, hang or
// produce a diagnostic without a usable position. (The libFuzzer target goes further.)
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "skip_policy.h"
#include "test_util.h"
#include "tierlift/assembly/printer.h"

namespace tierlift::assembly::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> seed_texts() {
  std::vector<std::string> out;
  for (const fs::path& dir :
       {fs::path(TIERLIFT_SOURCE_DIR) / "listings", fs::path(TIERLIFT_SHARED_DIR) / "corpus"}) {
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(dir, ec)) {
      if (e.path().extension() != ".vsh" && e.path().extension() != ".psh") continue;
      std::ifstream in(e.path(), std::ios::binary);
      std::ostringstream s;
      s << in.rdbuf();
      out.push_back(s.str());
    }
  }
  out.push_back("vs_2_0\n#define P(a, b) a ## b\nmov P(r, 1), P(c, 2)\n#define F(a,b) a b\n#if "
                "defined(F) && 1\nF(mov r0,, c[a0.x + 4])\n#endif\n");
  return out;
}

std::string mutate(std::string text, std::mt19937& rng) {
  static const std::string pieces[] = {"[",
                                       "]",
                                       "a0.x",
                                       "+",
                                       "-",
                                       "1-",
                                       "_bx2",
                                       ".xyzw",
                                       "#if 1",
                                       "#define",
                                       "#include \"x\"",
                                       "/*",
                                       "\xC2\xA0",
                                       "\xFF",
                                       "c[",
                                       "\n",
                                       ",",
                                       "def c0, 1e40",
                                       "1e-50",
                                       "!",
                                       "(",
                                       ")",
                                       "##"};
  int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits && !text.empty(); ++e) {
    size_t at = rng() % text.size();
    switch (rng() % 4) {
    case 0: text[at] = static_cast<char>(rng() % 256); break;
    case 1: text.erase(at, 1 + rng() % 8); break;
    case 2: text.insert(at, pieces[rng() % std::size(pieces)]); break;
    default: text.resize(at); break;
    }
  }
  return text;
}

// Where the line starting at `start` ends: '\n', or a '\r' not followed by '\n' (CR-only
// line endings count as line breaks, as the lexer counts them); npos at the end.
size_t line_end(const std::string& text, size_t start) {
  for (size_t i = start; i < text.size(); ++i)
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')))
      return i;
  return std::string::npos;
}

// A position that names a line of its file (a diagnostic at the end of a file may name the
// line after the last newline) and a column on that line or just past its end, counted in
// the file's bytes (a CRLF line's '\r' is one of them: "end of line" may point past it).
bool usable_position(const ir::SourceLoc& loc, const ir::SourceManager& sources) {
  if (!loc.valid() || loc.col == 0 || loc.file >= sources.files.size()) return false;
  const std::string& text = sources.files[loc.file].text;
  size_t start = 0;
  for (uint32_t line = 1; line < loc.line; ++line) {
    start = line_end(text, start);
    if (start == std::string::npos) return false;
    ++start;
  }
  const size_t end = std::min(line_end(text, start), text.size());
  return loc.col <= end - start + 1;
}

TEST(ParserMutation, MutatedListingsNeverCrashAndErrorsHavePositions) {
  if (::tierlift::test::required(::tierlift::test::kRequireCorpus)) {
    ASSERT_TRUE(fs::is_directory(fs::path(TIERLIFT_SHARED_DIR) / "corpus"))
        << "TIERLIFT_REQUIRE_CORPUS is set: the corpus seeds the mutations";
  }
  auto seeds = seed_texts();
  // TIERLIFT_MUTATION_ROUNDS / _SEED let a developer run a longer session locally.
  const char* rounds_env = std::getenv("TIERLIFT_MUTATION_ROUNDS");
  const char* seed_env = std::getenv("TIERLIFT_MUTATION_SEED");
  int rounds = rounds_env ? std::atoi(rounds_env) : 3000;
  std::mt19937 rng(seed_env ? static_cast<unsigned>(std::atoi(seed_env)) : 12345u);
  int parsed = 0, rejected = 0, errors = 0;
  for (int round = 0; round < rounds; ++round) {
    std::string text = mutate(seeds[static_cast<size_t>(round) % seeds.size()], rng);
    ParseResult r = parse_text(text, "<mutant>");
    if (r.program) {
      ++parsed;
      // Whatever parses must also print and re-parse to the same IR.
      ParseResult again = parse_text(print_program(*r.program));
      ASSERT_TRUE(again.program) << text;
      ASSERT_TRUE(ir::same_ir(*r.program, *again.program))
          << ir::ir_difference(*r.program, *again.program) << "\nprinted:\n"
          << print_program(*r.program) << "\nfrom:\n"
          << text;
    } else {
      ++rejected;
      ASSERT_TRUE(r.diags.has_errors()) << text;
      const std::string rendered = ir::render_text(r.diags, r.sources);
      for (const auto& d : r.diags.all()) {
        if (d.severity != ir::Severity::Error) continue;
        ++errors;
        ASSERT_TRUE(usable_position(d.loc, r.sources))
            << d.message << " at " << d.loc.file << ":" << d.loc.line << ":" << d.loc.col
            << "\nfrom:\n"
            << text;
        // The compilers' form, file:line:col: error:, is what a user sees.
        const std::string head = r.sources.files[d.loc.file].name + ":" +
                                 std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) +
                                 ": error: ";
        ASSERT_NE(rendered.find(head), std::string::npos) << head << "\n" << rendered;
      }
    }
  }
  EXPECT_GT(parsed, 0);
  EXPECT_GT(rejected, 0);
  EXPECT_GE(errors, rejected);
}

} // namespace
} // namespace tierlift::assembly::test
