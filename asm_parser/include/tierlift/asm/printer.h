// ir::Program → canonical assembly text. parse(print(p)) gives p again (same_ir).
#pragma once

#include <string>

#include "tierlift/ir/program.h"

namespace tierlift::as {

// Canonical form: underscore version line, lower-case mnemonics, one statement per line,
// shortest swizzles, floats in shortest round-trip form, "+" for co-issue.
std::string print_program(const ir::Program& program);
std::string print_instruction(const ir::Instruction& ins, ir::Profile profile);

}  // namespace tierlift::as
