// The error style of tierlift's library interfaces: a function that can fail returns Result<T>
// (a value, or the diagnostics that say why there is none) or Status (Result of nothing).
// Located diagnostics carry a SourceLoc; others (an unreadable file, no device) name a subject.
// The CLI renders them and turns them into exit codes; no library prints, and none throws
// to say an input is bad: the VM's preparation and the listing generator return their
// refusals as Results too.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tierlift/ir/diagnostic.h"

namespace tierlift::ir {

// What a failed call hands back: at least one error, possibly warnings and notes beside it.
struct Failure {
  std::vector<Diagnostic> diagnostics;
};

// A failure with one error. `subject` is what the message is about when there is no
// position (a path, "vulkan"); `rule` the short id of the rule broken ("io", "format", …).
Failure fail(std::string subject, std::string rule, std::string message);
// A failure with one positioned error.
Failure fail_at(SourceLoc loc, std::string rule, std::string message);
// Everything a sink collected (it must hold at least one error).
Failure fail(const DiagnosticSink& sink);
// A failure whose message is already rendered text ("file:line:col: error: …", the quoted
// source line and a caret, '\n'-ended), kept verbatim: no word is shortened, since it quotes
// the source its positions point into. For errors a library renders itself (a scene's JSON,
// glslang's log), whose positions no SourceManager of the caller knows.
Failure fail_rendered(std::string subject, std::string rule, std::string rendered);

template <class T> class [[nodiscard]] Result {
public:
  Result(T value) : value_(std::move(value)) {}
  Result(Failure failure) : diagnostics_(std::move(failure.diagnostics)) {
    assert(!diagnostics_.empty());
  }

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }

  T& value() & {
    assert(ok());
    return *value_;
  }
  const T& value() const& {
    assert(ok());
    return *value_;
  }
  T&& value() && {
    assert(ok());
    return std::move(*value_);
  }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }

  // Errors of a failure; warnings and notes of a success or a failure.
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  void add(Diagnostic d) { diagnostics_.push_back(std::move(d)); }
  // The first error's message, for callers that wrap it into a diagnostic of their own.
  std::string message() const {
    for (const Diagnostic& d : diagnostics_)
      if (d.severity == Severity::Error) return d.message;
    return {};
  }
  // The failure, to hand on to this function's own caller (only when !ok()).
  Failure failure() const& { return Failure{diagnostics_}; }
  Failure failure() && { return Failure{std::move(diagnostics_)}; }

private:
  std::optional<T> value_;
  std::vector<Diagnostic> diagnostics_;
};

struct Ok {};
using Status = Result<Ok>;
inline Status ok_status() {
  return Status(Ok{});
}

} // namespace tierlift::ir
