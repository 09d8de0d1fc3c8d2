// glslang reports "SEVERITY: name:line: 'token' : message" with no column; the column here is
// that of the quoted token in the source line (the first occurrence), which is where glslang
// stopped.
#include "glslang_messages.h"

#include <charconv>
#include <vector>

#include <fmt/format.h>

#include "tierlift/ir/diagnostic.h"

namespace tierlift::glsl {
namespace {

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

// The 1-based column of `token` in line `line` of `source`, 0 if absent.
uint32_t column_of(const std::vector<std::string_view>& lines, uint32_t line,
                   std::string_view token) {
  if (token.empty() || line == 0 || line > lines.size()) return 0;
  const size_t at = lines[line - 1].find(token);
  return at == std::string_view::npos ? 0 : static_cast<uint32_t>(at + 1);
}

struct Parsed {
  bool error = true;
  std::string file;
  uint32_t line = 0;
  std::string token, message;
};

// "ERROR: seed.frag:6: 'undefined_thing' : undeclared identifier": false when the line has
// no position (the summary lines).
bool parse_line(std::string_view l, Parsed& p) {
  if (l.starts_with("ERROR: "))
    l.remove_prefix(7);
  else if (l.starts_with("WARNING: ")) {
    l.remove_prefix(9);
    p.error = false;
  } else
    return false;
  // The position ends at ": '"; the file name may itself hold colons.
  const size_t quote = l.find(": '");
  if (quote == std::string_view::npos) return false;
  const std::string_view pos = l.substr(0, quote);
  const size_t colon = pos.rfind(':');
  if (colon == std::string_view::npos) return false;
  const std::string_view num = pos.substr(colon + 1);
  auto [ptr, ec] = std::from_chars(num.data(), num.data() + num.size(), p.line);
  if (ec != std::errc() || ptr != num.data() + num.size()) return false;
  p.file = std::string(pos.substr(0, colon));
  const std::string_view rest = l.substr(quote + 3);
  const size_t close = rest.find("' : ");
  if (close == std::string_view::npos) return false;
  p.token = std::string(rest.substr(0, close));
  std::string_view msg = rest.substr(close + 4);
  while (!msg.empty() && msg.back() == ' ') msg.remove_suffix(1);
  p.message = p.token.empty() ? std::string(msg) : fmt::format("'{}': {}", p.token, msg);
  return true;
}

} // namespace

std::string render_glslang_log(std::string_view log, const std::string& source,
                               const std::string& file_name) {
  const std::vector<std::string_view> src_lines = split_lines(source);
  ir::SourceManager sm;
  const uint32_t file = sm.add(file_name, source);
  ir::DiagnosticSink sink;
  std::string unpositioned;
  for (std::string_view l : split_lines(log)) {
    Parsed p;
    if (!parse_line(l, p)) {
      if (l.starts_with("ERROR: ") && l.find("compilation error") == std::string_view::npos)
        unpositioned += fmt::format("{}: error: {}\n", file_name, l.substr(7));
      continue;
    }
    if (p.message == "compilation terminated") continue; // glslang's follow-up, no news
    ir::SourceLoc loc;
    loc.file = file;
    // The preamble reports as line 0 or another name: place it on line 1 of the source.
    const bool ours = p.file == file_name && p.line >= 1 && p.line <= src_lines.size();
    loc.line = ours ? p.line : 1;
    const uint32_t col = ours ? column_of(src_lines, p.line, p.token) : 0;
    loc.col = col == 0 ? 1 : col;
    loc.length = col == 0 ? 1 : static_cast<uint32_t>(p.token.size());
    if (p.error)
      sink.error(loc, "glsl", p.message);
    else
      sink.warning(loc, "glsl", p.message);
  }
  if (sink.has_errors()) return ir::render_text(sink, sm);
  if (!unpositioned.empty()) return unpositioned;
  return fmt::format("{}: error: glslang failed without a message\n", file_name);
}

std::string render_at_name(const std::string& name, const std::string& message,
                           const std::string& source, const std::string& file_name) {
  const std::vector<std::string_view> lines = split_lines(source);
  ir::SourceLoc loc;
  loc.line = 1;
  loc.col = 1;
  loc.length = 1;
  for (size_t i = 0; i < lines.size(); ++i) {
    const size_t u = lines[i].find("uniform");
    if (u == std::string_view::npos) continue;
    const size_t at = lines[i].find(name, u);
    if (at == std::string_view::npos) continue;
    loc.line = static_cast<uint32_t>(i + 1);
    loc.col = static_cast<uint32_t>(at + 1);
    loc.length = static_cast<uint32_t>(name.size());
    break;
  }
  ir::SourceManager sm;
  loc.file = sm.add(file_name, source);
  ir::DiagnosticSink sink;
  sink.error(loc, "glsl", message);
  return ir::render_text(sink, sm);
}

} // namespace tierlift::glsl
