#include "report.h"

#include <cstdio>
#include <regex>
#include <sstream>

#include <fmt/format.h>

#include "tierlift/crash/crash.h"

namespace tierlift::cli {

Report::Report(std::string command, bool json) : command_(std::move(command)), json_(json) {}

void Report::add(std::string_view severity, std::string_view rule, const std::string& message,
                 const std::string& file) {
  if (!json_) {
    fmt::print(stderr, "tierlift {}: {}: {}\n", command_, severity, message);
    return;
  }
  diagnostics_.push_back({{"file", file},
                          {"line", 0},
                          {"column", 0},
                          {"length", 0},
                          {"severity", severity},
                          {"rule", rule},
                          {"message", message}});
}

void Report::error(std::string_view rule, const std::string& message, const std::string& file) {
  add("error", rule, message, file);
}

void Report::warning(std::string_view rule, const std::string& message, const std::string& file) {
  add("warning", rule, message, file);
}

namespace {
size_t g_error_limit = 100;
} // namespace

void Report::set_error_limit(size_t limit) {
  g_error_limit = limit;
}

size_t Report::error_limit() {
  return g_error_limit;
}

void Report::diagnostics(const ir::DiagnosticSink& sink, const ir::SourceManager& sources) {
  if (stopped_) return;
  // The diagnostics up to the limit; 50,000 errors would otherwise print megabytes.
  ir::DiagnosticSink shown;
  for (const ir::Diagnostic& d : sink.all()) {
    if (d.severity == ir::Severity::Error && g_error_limit != 0 && errors_shown_ == g_error_limit) {
      stopped_ = true;
      ir::Diagnostic note = d;
      note.severity = ir::Severity::Note;
      note.rule = "too-many-errors";
      note.message = fmt::format("too many errors ({} shown); stopping (--max-errors N changes "
                                 "the limit, 0 removes it)",
                                 g_error_limit);
      shown.add(std::move(note));
      break;
    }
    if (d.severity == ir::Severity::Error) ++errors_shown_;
    shown.add(d);
  }
  if (!json_) {
    std::fputs(ir::render_text(shown, sources).c_str(), stderr);
    return;
  }
  for (nlohmann::json& d : nlohmann::json::parse(ir::render_json(shown, sources)))
    diagnostics_.push_back(std::move(d));
}

void Report::output(std::string_view key, const std::string& text) {
  if (json_)
    result_[std::string(key)] = text;
  else
    std::fwrite(text.data(), 1, text.size(), stdout);
}

int Report::finish(int exit_code) {
  if (json_) {
    nlohmann::json doc = {{"command", command_},
                          {"exit_code", exit_code},
                          {"ok", exit_code == 0},
                          {"diagnostics", diagnostics_},
                          {"result", result_}};
    // Invalid UTF-8 from a listing becomes U+FFFD rather than an exception.
    fmt::print("{}\n", doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace));
    crash::document_written(); // a later crash adds its line, not a second document
  }
  std::fflush(stdout);
  return exit_code;
}

namespace {

// ir::render_text's output read back: "FILE:LINE:COL: SEVERITY: MESSAGE [RULE]", then the
// quoted source line and the caret line (both indented by four spaces), for each diagnostic.
// Each becomes one JSON diagnostic with its position; `length` is the caret's width. Text
// in another form is kept as one unpositioned diagnostic (rule `rule`, file `file`).
nlohmann::json parse_rendered(const std::string& rendered, std::string_view rule,
                              const std::string& file) {
  static const std::regex header(
      R"(^(.*):(\d+):(\d+): (error|warning|note): (.*?)(?: \[([A-Za-z0-9_.-]+)\])?$)");
  nlohmann::json out = nlohmann::json::array();
  std::istringstream in(rendered);
  std::string unstructured;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, header)) {
      out.push_back({{"file", m[1].str()},
                     {"line", std::stoul(m[2].str())},
                     {"column", std::stoul(m[3].str())},
                     {"length", 1},
                     {"severity", m[4].str()},
                     {"rule", m[6].matched ? m[6].str() : std::string(rule)},
                     {"message", m[5].str()}});
    } else if (line.starts_with("    ") && !out.empty()) {
      const size_t caret = line.find('^');
      if (caret != std::string::npos && line.find_first_not_of(" ^~") == std::string::npos)
        out.back()["length"] = line.find_last_of("^~") - caret + 1; // the caret line
    } else {
      unstructured += line + "\n";
    }
  }
  if (!unstructured.empty() || out.empty())
    out.push_back({{"file", file},
                   {"line", 0},
                   {"column", 0},
                   {"length", 0},
                   {"severity", "error"},
                   {"rule", rule},
                   {"message", unstructured.empty() ? rendered : unstructured}});
  return out;
}

} // namespace

void Report::rendered_error(std::string_view rule, const std::string& rendered,
                            const std::string& file) {
  if (json_) {
    for (nlohmann::json& d : parse_rendered(rendered, rule, file))
      diagnostics_.push_back(std::move(d));
  } else
    fmt::print(stderr, "{}{}", rendered, rendered.ends_with('\n') ? "" : "\n");
}

} // namespace tierlift::cli
