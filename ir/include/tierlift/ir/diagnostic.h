// Diagnostics in the compilers' form: "file:line:col: error: message", the source line and
// a caret. Every module reports through a DiagnosticSink; the CLI renders it as text or JSON.
#pragma once

#include <string>
#include <vector>

#include "tierlift/ir/source.h"

namespace tierlift::ir {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLoc loc;
  std::string message;
  std::string rule; // short id of the rule broken, e.g. "slot-limit", "read-before-write"
  // What the message is about when it has no position in a source file (a path, "vulkan"):
  // rendered in the file name's place.
  std::string subject;
};

// A message with every word (run of non-blanks) longer than kMaxEchoedWord bytes cut to
// its first kEchoedWordHead bytes, "…" and its length: a diagnostic echoes the offending
// token, and a 50 MB register index must not become 50 MB of standard error.
inline constexpr size_t kMaxEchoedWord = 200;
inline constexpr size_t kEchoedWordHead = 96;
std::string shorten_long_words(std::string message);

class DiagnosticSink {
public:
  void error(SourceLoc loc, std::string rule, std::string message) {
    add({Severity::Error, loc, std::move(message), std::move(rule), {}});
  }
  void warning(SourceLoc loc, std::string rule, std::string message) {
    add({Severity::Warning, loc, std::move(message), std::move(rule), {}});
  }
  void note(SourceLoc loc, std::string rule, std::string message) {
    add({Severity::Note, loc, std::move(message), std::move(rule), {}});
  }
  void add(Diagnostic d) {
    d.message = shorten_long_words(std::move(d.message));
    if (d.severity == Severity::Error) ++errors_;
    if (d.severity == Severity::Warning) ++warnings_;
    list_.push_back(std::move(d));
  }
  bool has_errors() const { return errors_ > 0; }
  size_t error_count() const { return errors_; }
  size_t warning_count() const { return warnings_; }
  const std::vector<Diagnostic>& all() const { return list_; }
  void clear() {
    list_.clear();
    errors_ = warnings_ = 0;
  }

private:
  std::vector<Diagnostic> list_;
  size_t errors_ = 0, warnings_ = 0;
};

// "file:12:5: error: message [rule]\n    line text\n    ^~~~\n"
std::string render_text(const Diagnostic& d, const SourceManager& sm);
// Every diagnostic of the sink, in order.
std::string render_text(const DiagnosticSink& sink, const SourceManager& sm);
// One JSON object per diagnostic: {"file","line","column","length","severity","rule","message"}.
std::string render_json(const DiagnosticSink& sink, const SourceManager& sm);

} // namespace tierlift::ir
