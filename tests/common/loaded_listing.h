// A listing loaded from bytes (text, a token stream or a token array) as the CLI loads it,
// with its diagnostics rendered: shared by the loader and validator tests.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "tierlift/assembly/load.h"
#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/result_diagnostics.h"

namespace tierlift::test {

struct LoadedListing {
  ir::SourceManager sm;
  ir::DiagnosticSink diags;
  // Empty until load_bytes fills it (assembly::Loaded has no "not loaded yet" state of its own).
  std::optional<assembly::Loaded> loaded;
  const assembly::Loaded& r() const { return *loaded; }
  std::string rendered;
  // Diagnostics of `severity` under `rule`.
  size_t count(ir::Severity severity, const std::string& rule) const {
    size_t n = 0;
    for (const auto& d : diags.all()) n += d.severity == severity && d.rule == rule;
    return n;
  }
};

inline LoadedListing load_bytes(std::string bytes, std::string name = "shader.pso",
                                assembly::LoadOptions options = {}) {
  LoadedListing l;
  uint32_t f = l.sm.add(std::move(name), std::move(bytes));
  l.loaded = assembly::load_listing(f, l.sm, options);
  ir::add_all(l.diags, l.loaded->program.diagnostics());
  l.rendered = ir::render_text(l.diags, l.sm);
  return l;
}

} // namespace tierlift::test
