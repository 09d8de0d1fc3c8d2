// Integer constant expressions of #if / #elif (after defined() and macro expansion).
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "tierlift/assembly/preprocessor.h"

namespace tierlift::assembly::detail {

// Evaluates the tokens as a C integer constant expression in 64-bit two's complement.
// Identifiers that are left count as 0, as in C. Returns nullopt after reporting an error
// (rule "preprocessor") at `where` or at the offending token.
std::optional<int64_t> eval_pp_expression(std::span<const Token> tokens, ir::SourceLoc where,
                                          ir::DiagnosticSink& diags);

} // namespace tierlift::assembly::detail
