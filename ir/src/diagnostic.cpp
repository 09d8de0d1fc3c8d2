#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/result.h"
#include "tierlift/ir/result_diagnostics.h"

#include <cassert>

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

// Length of the valid UTF-8 sequence starting at s[i], or 0 when it is not valid.
size_t utf8_length(std::string_view s, size_t i) {
  unsigned char c = static_cast<unsigned char>(s[i]);
  size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) >> 6) != 2) return 0;
  return n;
}

// A byte that is not UTF-8, read as Windows-1252 (the code page legacy listings' comments
// are most often in), as UTF-8; "?" for the five bytes that code page leaves unassigned.
std::string windows1252(unsigned char b) {
  static constexpr uint16_t k80[32] = {
      0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
      0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
      0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};
  const uint32_t cp = b >= 0xA0 ? b : k80[b - 0x80];
  if (cp == 0) return "?";
  std::string out;
  if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
  } else {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
  }
  out += static_cast<char>(0x80 | (cp & 0x3F));
  return out;
}

// The quoted line made printable, and the caret's indentation counted in characters, not
// bytes: tabs become one space, control bytes become '?', a byte that is not UTF-8 is read
// as Windows-1252 (one byte, one column: the positions are those of the file as saved), and
// a UTF-8 character (the no-break spaces of web-copied listings) takes one column.
struct QuotedLine {
  std::string text;
  size_t caret_indent = 0;
};

QuotedLine quote(std::string_view line, size_t byte_col) {
  QuotedLine q;
  size_t chars = 0;
  for (size_t i = 0; i < line.size();) {
    if (i < byte_col) q.caret_indent = chars + 1;
    unsigned char u = static_cast<unsigned char>(line[i]);
    size_t n = utf8_length(line, i);
    if (n == 0) {
      q.text += windows1252(u);
      n = 1;
    } else if (n == 1) {
      q.text += line[i] == '\t' ? ' ' : (u < 0x20 || u == 0x7f) ? '?' : line[i];
    } else if (n == 2 && u == 0xC2 && static_cast<unsigned char>(line[i + 1]) == 0xA0) {
      q.text += ' '; // no-break space
    } else {
      q.text.append(line.substr(i, n));
    }
    i += n;
    ++chars;
  }
  if (byte_col == 0) q.caret_indent = 0;
  if (byte_col >= line.size()) q.caret_indent = chars;
  return q;
}

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

} // namespace

std::string shorten_long_words(std::string message) {
  if (message.size() <= kMaxEchoedWord) return message; // the common case: nothing to cut
  std::string out;
  for (size_t i = 0; i < message.size();) {
    if (blank(message[i])) {
      out += message[i++];
      continue;
    }
    size_t end = i;
    while (end < message.size() && !blank(message[end])) ++end;
    const size_t len = end - i;
    if (len <= kMaxEchoedWord) {
      out.append(message, i, len);
    } else {
      size_t head = kEchoedWordHead; // back up to a UTF-8 character boundary
      while (head > 0 && (static_cast<unsigned char>(message[i + head]) & 0xC0) == 0x80) --head;
      out.append(message, i, head);
      out += fmt::format("… ({} bytes)", len);
    }
    i = end;
  }
  return out;
}

std::string render_text(const Diagnostic& d, const SourceManager& sm) {
  std::string out;
  if (d.loc.valid())
    out = fmt::format("{}:{}:{}: {}: {}", file_name(sm, d.loc), d.loc.line, d.loc.col,
                      severity_name(d.severity), d.message);
  else if (d.loc.has_offset())
    out = fmt::format("{}:+0x{:x}: {}: {}", file_name(sm, d.loc), d.loc.byte_offset,
                      severity_name(d.severity), d.message);
  else if (!d.subject.empty())
    out = fmt::format("{}: {}: {}", d.subject, severity_name(d.severity), d.message);
  else
    out = fmt::format("{}: {}: {}", file_name(sm, d.loc), severity_name(d.severity), d.message);
  if (!d.rule.empty()) out += fmt::format(" [{}]", d.rule);
  out += '\n';
  if (d.loc.valid()) {
    std::string line = sm.line_text(d.loc.file, d.loc.line);
    if (line.size() > 400) line.resize(400); // a 10 MB single-line file must not flood
    size_t col = d.loc.col > 0 ? d.loc.col - 1 : 0;
    QuotedLine q = quote(line, col);
    size_t len = d.loc.length > 0 ? d.loc.length : 1;
    if (len > 200) len = 200;
    out += "    " + q.text + "\n";
    out += "    " + std::string(q.caret_indent, ' ') + "^" + std::string(len - 1, '~') + "\n";
  }
  return out;
}

std::string render_text(const DiagnosticSink& sink, const SourceManager& sm) {
  return render_text(sink.all(), sm);
}

std::string render_text(const std::vector<Diagnostic>& ds, const SourceManager& sm) {
  std::string out;
  for (const Diagnostic& d : ds) out += render_text(d, sm);
  return out;
}

std::string render_json(const DiagnosticSink& sink, const SourceManager& sm) {
  nlohmann::json arr = nlohmann::json::array();
  for (const Diagnostic& d : sink.all()) {
    nlohmann::json j;
    j["file"] =
        d.loc.valid() || d.loc.has_offset() || d.subject.empty() ? file_name(sm, d.loc) : d.subject;
    j["line"] = d.loc.line;
    j["column"] = d.loc.col;
    j["length"] = d.loc.length;
    if (d.loc.has_offset()) j["offset"] = d.loc.byte_offset; // a token stream's byte offset
    j["severity"] = severity_name(d.severity);
    j["rule"] = d.rule;
    j["message"] = d.message;
    arr.push_back(std::move(j));
  }
  return arr.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

Failure fail(std::string subject, std::string rule, std::string message) {
  Diagnostic d{Severity::Error, SourceLoc{}, shorten_long_words(std::move(message)),
               std::move(rule), std::move(subject)};
  return Failure{{std::move(d)}};
}

Failure fail_at(SourceLoc loc, std::string rule, std::string message) {
  return Failure{{Diagnostic{
      Severity::Error, loc, shorten_long_words(std::move(message)), std::move(rule), {}}}};
}

Failure fail_rendered(std::string subject, std::string rule, std::string rendered) {
  return Failure{{Diagnostic{Severity::Error, SourceLoc{}, std::move(rendered), std::move(rule),
                             std::move(subject)}}};
}

Failure fail(const DiagnosticSink& sink) {
  assert(sink.has_errors());
  return Failure{sink.all()};
}

} // namespace tierlift::ir
