// A listing loaded from bytes (text, a token stream or a token array) as the CLI loads it,
// with its diagnostics rendered: shared by the loader and validator tests.
#pragma once

#include <cstddef>
#include <string>

#include "tierlift/asm/load.h"
#include "tierlift/ir/diagnostic.h"

namespace tierlift::test {

struct LoadedListing {
  ir::SourceManager sm;
  ir::DiagnosticSink diags;
  as::LoadResult r;
  std::string rendered;
  // Diagnostics of `severity` under `rule`.
  size_t count(ir::Severity severity, const std::string& rule) const {
    size_t n = 0;
    for (const auto& d : diags.all()) n += d.severity == severity && d.rule == rule;
    return n;
  }
};

inline LoadedListing load_bytes(std::string bytes, std::string name = "shader.pso",
                                as::LoadOptions options = {}) {
  LoadedListing l;
  uint32_t f = l.sm.add(std::move(name), std::move(bytes));
  l.r = as::load_listing(f, l.sm, l.diags, options);
  l.rendered = ir::render_text(l.diags, l.sm);
  return l;
}

} // namespace tierlift::test
