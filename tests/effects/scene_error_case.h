// A bad scene and what its loader must say: the field's JSON pointer at line:col of its
// value, the reason, then the source line and a caret under that column. Shared by the
// scene test files, each with its own list of cases.
#pragma once

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>

#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {

// The shipped scenes' folder, where the scene texts of the tests resolve relative paths.
inline const std::filesystem::path kScenes =
    std::filesystem::path(TIERLIFT_SOURCE_DIR) / "listings" / "scenes";

// `text` loaded as the scene file "s.json" of the shipped scenes' folder.
inline ir::Result<Scene> parse_shipped(const std::string& text) {
  return parse_scene(text, "s.json", kScenes.string());
}

struct SceneErrorCase {
  const char* text;
  const char* where; // "s.json:L:C: error: /pointer"
  const char* says;
};

// How a case prints (GetParam) and its test name: the field and the reason, not the bytes of
// the struct ("Fields/SceneErrors.ReportsPositionedError/glow_tier_0").
inline void PrintTo(const SceneErrorCase& c, std::ostream* os) {
  *os << c.where << " (" << c.says << ")";
}
inline std::string scene_case_name(const ::testing::TestParamInfo<SceneErrorCase>& info) {
  std::string where = info.param.where;
  const size_t slash = where.find(" /");
  std::string name;
  for (char ch : slash == std::string::npos ? std::string("file") : where.substr(slash + 2))
    name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return name + "_" + std::to_string(info.index);
}

// `s` is the load of `b.text`: it failed, names the place and the reason, and has a caret
// line; when `where` starts with "file:line:col:", the caret sits under that column (the
// source line and the caret line share an indent of 4 when the source line is not blank).
inline void expect_positioned_scene_error(const ir::Result<Scene>& s, const SceneErrorCase& b) {
  ASSERT_FALSE(s) << b.text;
  EXPECT_NE(s.message().find(b.where), std::string::npos) << s.message();
  EXPECT_NE(s.message().find(b.says), std::string::npos) << s.message();
  const size_t caret_line = s.message().find('^');
  ASSERT_NE(caret_line, std::string::npos) << s.message();
  const std::string head = b.where;
  const size_t c1 = head.find(':'), c2 = head.find(':', c1 + 1), c3 = head.find(':', c2 + 1);
  if (c3 == std::string::npos || c3 == c2 + 1 || head.find_first_not_of("0123456789", c2 + 1) != c3)
    return; // "error: /pointer" alone: no column to hold the caret against
  const int col = std::stoi(head.substr(c2 + 1, c3 - c2 - 1));
  const size_t line_start = s.message().rfind('\n', caret_line) + 1;
  const size_t src_start = s.message().rfind('\n', line_start - 2) + 1;
  const std::string src = s.message().substr(src_start, line_start - 1 - src_start);
  const size_t indent = src.find_first_not_of(' ');
  EXPECT_EQ(caret_line - line_start, size_t(col - 1 + (indent == std::string::npos ? 0 : 4)))
      << s.message();
}

} // namespace tierlift::effects
