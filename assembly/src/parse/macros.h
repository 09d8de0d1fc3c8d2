// Macro table and expansion for the preprocessor (object-like and function-like macros).
#pragma once

#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/assembly/preprocessor.h"

namespace tierlift::assembly::detail {

struct Macro {
  bool function_like = false;
  std::vector<std::string_view> params;
  std::vector<Token> body;
  bool active = false; // being expanded right now: a macro never expands inside itself
};

class MacroTable {
public:
  // Tokens made by ## pasting keep their text here (the token stream's storage).
  explicit MacroTable(std::vector<std::unique_ptr<std::string>>& storage) : storage_(&storage) {}

  void define(std::string name, Macro m) { macros_[std::move(name)] = std::move(m); }
  void undefine(std::string_view name) {
    if (auto it = macros_.find(name); it != macros_.end()) macros_.erase(it);
  }
  bool defined(std::string_view name) const { return macros_.find(name) != macros_.end(); }
  bool empty() const { return macros_.empty(); }

  // Expands every macro use in `in` (one source line) and appends the result to `out`.
  // Expanded tokens carry the position of the outermost macro use. Returns false after
  // reporting an error (rule "preprocessor"); `out` then holds a partial expansion.
  bool expand(std::span<const Token> in, std::vector<Token>& out, ir::DiagnosticSink& diags);

private:
  bool expand_impl(std::span<const Token> in, std::vector<Token>& out, const ir::SourceLoc* use,
                   int depth);
  bool substitute_call(const Macro& m, std::span<const Token> in, size_t& i, ir::SourceLoc loc,
                       int depth, std::vector<Token>& subst);
  bool push(std::vector<Token>& out, Token t, const ir::SourceLoc* use);
  size_t modifier_split(std::string_view name) const;
  bool expand_with_modifier(const Token& t, size_t us, std::vector<Token>& out,
                            const ir::SourceLoc* use, int depth);
  void paste(std::vector<Token>& toks);

  std::map<std::string, Macro, std::less<>> macros_;
  std::vector<std::unique_ptr<std::string>>* storage_;
  ir::DiagnosticSink* diags_ = nullptr;
  size_t budget_ = 0;     // tokens the current line may still produce
  size_t total_used_ = 0; // tokens produced by all expansions so far
};

} // namespace tierlift::assembly::detail
