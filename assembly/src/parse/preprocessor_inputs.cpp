// What the preprocessor read and what a listing needs it for (preprocessor.h):
// included_files for the commands that must not overwrite an input, first_preprocessor_use
// for `fmt`, which prints the IR and so cannot keep directives or macro uses.
#include <algorithm>

#include "tierlift/assembly/preprocessor.h"

namespace tierlift::assembly {

std::vector<std::string> included_files(const ir::SourceManager& sm) {
  std::vector<std::string> out;
  for (const ir::SourceFile& f : sm.files)
    if (f.included && std::find(out.begin(), out.end(), f.name) == out.end()) out.push_back(f.name);
  return out;
}

std::optional<PreprocessorUse> first_preprocessor_use(uint32_t file, const ir::SourceManager& sm,
                                                      const ParseOptions& options) {
  if (file >= sm.files.size()) return std::nullopt;
  ir::DiagnosticSink scratch; // the listing parsed already; its lexing errors were said
  LineLexer lexer(file, sm.files[file].text, scratch);
  std::vector<Token> line;
  while (lexer.next_line(line)) {
    if (line.size() > 1 && line[0].kind == TokKind::Punct && line[0].text == "#") {
      PreprocessorUse use{line[0].loc, "#"};
      if (line[1].kind == TokKind::Ident) {
        use.what += std::string(line[1].text);
        use.loc.length = line[1].loc.col + line[1].loc.length - line[0].loc.col;
      }
      return use;
    }
    for (const Token& t : line) {
      if (t.kind != TokKind::Ident) continue;
      for (const auto& [name, value] : options.defines)
        if (t.text == name) return PreprocessorUse{t.loc, "macro " + name};
    }
    line.clear();
  }
  return std::nullopt;
}

} // namespace tierlift::assembly
