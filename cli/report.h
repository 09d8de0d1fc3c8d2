// What every command prints besides its own output, in one of two forms: text (diagnostics
// with carets and "tierlift CMD: error: ..." lines on standard error) or, with --json, one
// JSON document on standard output (docs/command-line.md has the schema):
//   {"command": "check", "exit_code": 1, "ok": false,
//    "diagnostics": [{"file", "line", "column", "length", "severity", "rule", "message"}],
//    "result": {...what the command computed...}}
// I/O and usage errors are diagnostics too (line 0, rule "io" or "usage"), so a script
// reads every outcome from the same place.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/source.h"

namespace tierlift::cli {

class Report {
public:
  Report(std::string command, bool json);

  bool json() const { return json_; }
  // An error or warning not tied to a line of a listing: `rule` is "io", "usage", "device",
  // "agreement", ...; `file` names the file when there is one.
  void error(std::string_view rule, const std::string& message, const std::string& file = "");
  void warning(std::string_view rule, const std::string& message, const std::string& file = "");
  // One error whose message is rendered diagnostics already (a scene's, effects/scene.h):
  // the text as it is, or under --json one `rule` error naming `file`.
  void rendered_error(std::string_view rule, const std::string& rendered, const std::string& file);
  // Diagnostics of a listing (positions, carets). At most error_limit() errors are shown per
  // run, as compilers do: the one after the limit and everything after it are replaced by
  // one note "too many errors; stopping".
  void diagnostics(const ir::DiagnosticSink& sink, const ir::SourceManager& sources);
  // --max-errors N (0: no limit); 100 by default. One setting for the process.
  static void set_error_limit(size_t limit);
  static size_t error_limit();
  // Text that is the command's output: standard output as is, or result[key] in JSON.
  void output(std::string_view key, const std::string& text);
  // The command-specific part of the JSON document.
  nlohmann::json& result() { return result_; }
  // Prints the JSON document (in JSON mode) and returns `exit_code`.
  int finish(int exit_code);

private:
  void add(std::string_view severity, std::string_view rule, const std::string& message,
           const std::string& file);
  std::string command_;
  bool json_;
  nlohmann::json diagnostics_ = nlohmann::json::array();
  nlohmann::json result_ = nlohmann::json::object();
  size_t errors_shown_ = 0;
  bool stopped_ = false; // the error limit was reached: no more listing diagnostics
};

} // namespace tierlift::cli
