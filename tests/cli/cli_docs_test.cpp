// What the docs and --help say about the command line (issue 32, item 12): the scenes
// README's tables are well-formed Markdown, command-line.md no longer says `report` has
// only --stress, and --image's help names PFM.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "tierlift/ir/ps1x_range.h"

using tierlift::test::read_all;
using tierlift::test::run_cli;

namespace {

// Cell separators of a table row: '|' outside `code` and not escaped.
size_t separators(const std::string& row) {
  size_t n = 0;
  bool code = false;
  for (size_t i = 0; i < row.size(); ++i) {
    if (row[i] == '`') code = !code;
    if (row[i] == '|' && !code && (i == 0 || row[i - 1] != '\\')) ++n;
  }
  return n;
}

bool separator_line(const std::string& line) {
  return line.size() > 2 && line.front() == '|' &&
         line.find_first_not_of("|-: ") == std::string::npos;
}

// Each table: a blank line (or the start) before it, a header, its separator line, and every
// row with as many cells as the header. One message per problem.
std::vector<std::string> table_problems(const std::string& text) {
  std::vector<std::string> lines, out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  bool fence = false;
  size_t header = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.starts_with("```")) fence = !fence;
    if (fence || !l.starts_with("|")) {
      header = 0;
      continue;
    }
    if (header == 0) { // a table starts
      header = separators(l);
      if (i > 0 && !lines[i - 1].empty())
        out.push_back("line " + std::to_string(i + 1) + ": table not after a blank line");
      if (i + 1 >= lines.size() || !separator_line(lines[i + 1]))
        out.push_back("line " + std::to_string(i + 1) + ": table row without a header");
    } else if (separators(l) != header) {
      out.push_back("line " + std::to_string(i + 1) + ": " + std::to_string(separators(l)) +
                    " separators, the header has " + std::to_string(header));
    }
  }
  return out;
}

TEST(CliDocs, ScenesReadmeTablesAreWellFormed) {
  const std::string readme =
      read_all(std::string(TIERLIFT_SOURCE_DIR) + "/listings/scenes/README.md");
  ASSERT_FALSE(readme.empty());
  const std::vector<std::string> problems = table_problems(readme);
  EXPECT_TRUE(problems.empty()) << problems.size() << " problems, first: " << problems.front();
}

TEST(CliDocs, TableCheckFindsBrokenTables) {
  EXPECT_TRUE(table_problems("| a | b |\n| --- | --- |\n| 1 | 2 |\n").empty());
  EXPECT_EQ(table_problems("| a | b |\n| --- | --- |\n| 1 | 2 | 3 |\n").size(), 1u);
  EXPECT_EQ(table_problems("![x](x.png)\n| 1 | 2 |\n").size(), 2u); // glued on, no header
  EXPECT_TRUE(table_problems("| a |\n| --- |\n| `x|y` and \\| |\n").empty());
}

TEST(CliDocs, CommandLineDocNoLongerLimitsReportToStress) {
  const std::string doc = read_all(std::string(TIERLIFT_SOURCE_DIR) + "/docs/command-line.md");
  EXPECT_EQ(doc.find("has only `--stress`"), std::string::npos);
  EXPECT_NE(doc.find("## `tierlift diff`"), std::string::npos);
}

TEST(CliDocs, ImageHelpNamesPfm) {
  for (const char* command : {"glow", "report"}) {
    auto r = run_cli(std::string(command) + " --help");
    ASSERT_EQ(r.exit_code, 0);
    const size_t at = r.out.find("--image TEXT");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_NE(r.out.substr(at, 200).find("PFM"), std::string::npos) << command;
  }
}

// Every flag of the command line is in docs/command-line.md; these six were in no doc.
TEST(CliDocs, SmallerFlagsAreDocumented) {
  const std::string doc = read_all(std::string(TIERLIFT_SOURCE_DIR) + "/docs/command-line.md");
  for (const char* flag : {"`run --pixel-center", "`run --probe", "`run --subtexel-bits",
                           "`run --threads", "`--quiet`", "`assemble --c-name"})
    EXPECT_NE(doc.find(flag), std::string::npos) << flag;
}

// --ps1x-max's help prints the presets from the one table (ir::kPs1xPresets), every one.
TEST(CliDocs, Ps1xMaxHelpListsTheTable) {
  for (const char* command : {"run", "glow"}) {
    auto r = run_cli(std::string(command) + " --help");
    ASSERT_EQ(r.exit_code, 0);
    const size_t at = r.out.find("--ps1x-max");
    ASSERT_NE(at, std::string::npos) << r.out;
    const std::string help = r.out.substr(at, 400);
    EXPECT_NE(help.find(tierlift::ir::ps1x_choices()), std::string::npos) << command << help;
    for (const tierlift::ir::Ps1xPreset& p : tierlift::ir::kPs1xPresets)
      EXPECT_NE(help.find(std::string(p.name) + " ("), std::string::npos) << command << p.name;
  }
}

} // namespace
