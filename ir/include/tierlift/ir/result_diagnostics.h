// What a caller does with the diagnostics of an ir::Result (result.h): tell one kind of
// failure from another by its rule, collect them into a sink beside a listing's own, render
// them against the SourceManager their positions point into.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/result.h"

namespace tierlift::ir {

// True when `r` failed and its first error is of `rule`: how a caller tells one kind of
// failure from the others (a file that cannot be read from one that is wrong, no Vulkan
// device from a broken one) without a second error channel.
template <class T> bool failed_with(const Result<T>& r, std::string_view rule) {
  if (r.ok()) return false;
  for (const Diagnostic& d : r.diagnostics())
    if (d.severity == Severity::Error) return d.rule == rule;
  return false;
}

// Appends `ds` to `sink`, in order: a caller that reports several loads together renders
// them as one list.
inline void add_all(DiagnosticSink& sink, const std::vector<Diagnostic>& ds) {
  for (const Diagnostic& d : ds) sink.add(d);
}

// Every diagnostic of `ds`, in order (render_text of a sink, for a Result's list).
std::string render_text(const std::vector<Diagnostic>& ds, const SourceManager& sm);

} // namespace tierlift::ir
