// ir::Program → canonical assembly text. parse(print(p)) gives p again (same_ir).
#pragma once

#include <string>
#include <string_view>

#include "tierlift/ir/program.h"

namespace tierlift::assembly {

// Canonical form: underscore version line, lower-case mnemonics, one statement per line,
// shortest swizzles, floats in shortest round-trip form, "+" for co-issue.
// Details: instruction modifiers in the order shift (_x2.._d8), _sat, _pp, _centroid;
// vertex dcl names its usage and leaves index 0 out ("dcl_texcoord v3", "dcl_normal2 v1");
// pixel dcl has no usage ("dcl_pp t0.xy"), samplers "dcl_2d s0"; relative addressing as
// "c[a0.x + 4]" / "c[aL]"; NaN constants as their raw bits "0x7fc00001" (read back by the
// parser), other floats via fmt "{}" (1, 0.5, -0, 1e-07, inf); comment blocks of a token
// stream where they stood, as print_comment_block writes them.
std::string print_program(const ir::Program& program);
std::string print_instruction(const ir::Instruction& ins, ir::Profile profile);
std::string print_declaration(const ir::Declaration& d, ir::Profile profile);
std::string print_definition(const ir::ConstDef& d);
// A comment block of the token stream as the parser reads it back: "//!comment" and its
// words in hexadecimal, eight a line, further lines marked "//!comment+" (one or more lines,
// no final newline).
std::string print_comment_block(const ir::CommentBlock& c);

// print_program, keeping the comments and paragraphs of `source` (the text of sm.files[file]
// the program was parsed from): comment-only lines stay where they were, a statement's
// trailing comment stays on its line, runs of blank lines become one blank line. Lines of
// preprocessor directives are left out (their statements print expanded, as always).
// Parsing the result gives the same IR.
std::string print_program_with_comments(const ir::Program& program, std::string_view source,
                                        uint32_t file);

} // namespace tierlift::assembly
