// Shared by the draw tests: programs parsed from listing text or from listings/, with the
// parser's (and the validator's) diagnostics in the failure message when they are refused.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"
#include "tierlift/ir/diagnostic.h"

namespace tierlift::cpu::test {

// `text` parsed (named `name` in diagnostics) and, with `validate`, checked by the validator;
// null when it does not parse. Some tests draw programs the validator would refuse.
inline std::shared_ptr<const ir::Program>
parsed(const std::string& text, const std::string& name = "<test>", bool validate = false) {
  auto r = assembly::parse_text(text, name);
  if (!r.program) {
    ADD_FAILURE() << name << ": " << ir::render_text(r.diags, r.sources);
    return nullptr;
  }
  if (validate) {
    EXPECT_TRUE(assembly::validate(*r.program, r.diags)) << ir::render_text(r.diags, r.sources);
  }
  return std::make_shared<const ir::Program>(*r.program);
}

// listings/<path> parsed and validated.
inline std::shared_ptr<const ir::Program> listing_file(const std::string& path) {
  std::ifstream in(std::string(TIERLIFT_SOURCE_DIR) + "/listings/" + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return parsed(ss.str(), path, true);
}

} // namespace tierlift::cpu::test
