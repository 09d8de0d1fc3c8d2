#include "tierlift/ir/diagnostic.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace tierlift::ir {
namespace {

std::string_view severity_name(Severity s) {
  switch (s) {
  case Severity::Error: return "error";
  case Severity::Warning: return "warning";
  case Severity::Note: return "note";
  }
  return "error";
}

std::string file_name(const SourceManager& sm, const SourceLoc& loc) {
  if (loc.file < sm.files.size()) return sm.files[loc.file].name;
  return "<unknown>";
}

// Keep the quoted line printable: tabs become one space so the caret lines up, other
// control bytes become '?'.
std::string printable(std::string_view line) {
  std::string out;
  out.reserve(line.size());
  for (char c : line) {
    unsigned char u = static_cast<unsigned char>(c);
    if (c == '\t') out += ' ';
    else if (u < 0x20 || u == 0x7f) out += '?';
    else out += c;
  }
  return out;
}

}  // namespace

std::string render_text(const Diagnostic& d, const SourceManager& sm) {
  std::string out;
  if (d.loc.valid())
    out = fmt::format("{}:{}:{}: {}: {}", file_name(sm, d.loc), d.loc.line, d.loc.col,
                      severity_name(d.severity), d.message);
  else
    out = fmt::format("{}: {}: {}", file_name(sm, d.loc), severity_name(d.severity), d.message);
  if (!d.rule.empty()) out += fmt::format(" [{}]", d.rule);
  out += '\n';
  if (d.loc.valid()) {
    std::string line = sm.line_text(d.loc.file, d.loc.line);
    if (line.size() > 400) line.resize(400);  // a 10 MB single-line file must not flood
    out += "    " + printable(line) + "\n";
    size_t col = d.loc.col > 0 ? d.loc.col - 1 : 0;
    if (col > line.size()) col = line.size();
    size_t len = d.loc.length > 0 ? d.loc.length : 1;
    if (len > 200) len = 200;
    out += "    " + std::string(col, ' ') + "^" + std::string(len - 1, '~') + "\n";
  }
  return out;
}

std::string render_text(const DiagnosticSink& sink, const SourceManager& sm) {
  std::string out;
  for (const Diagnostic& d : sink.all()) out += render_text(d, sm);
  return out;
}

std::string render_json(const DiagnosticSink& sink, const SourceManager& sm) {
  nlohmann::json arr = nlohmann::json::array();
  for (const Diagnostic& d : sink.all()) {
    nlohmann::json j;
    j["file"] = file_name(sm, d.loc);
    j["line"] = d.loc.line;
    j["column"] = d.loc.col;
    j["length"] = d.loc.length;
    j["severity"] = severity_name(d.severity);
    j["rule"] = d.rule;
    j["message"] = d.message;
    arr.push_back(std::move(j));
  }
  return arr.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace tierlift::ir
