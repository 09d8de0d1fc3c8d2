#include "report.h"

#include <cstdio>

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

void Report::diagnostics(const ir::DiagnosticSink& sink, const ir::SourceManager& sources) {
  if (!json_) {
    std::fputs(ir::render_text(sink, sources).c_str(), stderr);
    return;
  }
  for (nlohmann::json& d : nlohmann::json::parse(ir::render_json(sink, sources)))
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

void Report::rendered_error(std::string_view rule, const std::string& rendered,
                            const std::string& file) {
  if (json_)
    error(rule, rendered, file);
  else
    fmt::print(stderr, "{}{}", rendered, rendered.ends_with('\n') ? "" : "\n");
}

} // namespace tierlift::cli
