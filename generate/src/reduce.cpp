// reduce_listing: ddmin over the listing's lines (Zeller and Hildebrandt's delta debugging,
// complements only), then operand simplifications one at a time, until a round changes
// nothing. Every candidate is judged by the predicate alone, so whatever the predicate
// demands (it parses and validates, then checks the failure) holds for the result.
#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <vector>

#include "tierlift/generate/generate.h"

namespace tierlift::gen {
namespace {

using Lines = std::vector<std::string>;
using Predicate = std::function<bool(const std::string&)>;

std::string join(const Lines& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

Lines split(const std::string& text) {
  Lines lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    if (l.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(l);
  return lines;
}

// ddmin: remove ever smaller chunks while the predicate holds.
Lines ddmin(Lines lines, const Predicate& fails) {
  size_t n = 2;
  while (lines.size() >= 2) {
    const size_t chunk = (lines.size() + n - 1) / n;
    bool reduced = false;
    for (size_t start = 0; start < lines.size(); start += chunk) {
      Lines rest(lines.begin(), lines.begin() + static_cast<long>(start));
      rest.insert(rest.end(),
                  lines.begin() + static_cast<long>(std::min(start + chunk, lines.size())),
                  lines.end());
      if (fails(join(rest))) {
        lines = std::move(rest);
        n = std::max<size_t>(n - 1, 2);
        reduced = true;
        break;
      }
    }
    if (reduced) continue;
    if (n >= lines.size()) break;
    n = std::min(2 * n, lines.size());
  }
  return lines;
}

// "mad_sat r0.xy, -r1_bx2.zw, c2" → head "mad_sat", operands {"r0.xy", "-r1_bx2.zw", "c2"}.
struct Statement {
  std::string head;
  std::vector<std::string> ops;
  std::string text() const {
    std::string s = head;
    for (size_t i = 0; i < ops.size(); ++i) s += (i ? ", " : " ") + ops[i];
    return s;
  }
};

Statement parse_statement(const std::string& line) {
  Statement s;
  const size_t b = line.find_first_not_of(" \t");
  const size_t e = line.find_first_of(" \t", b);
  s.head = line.substr(b, e == std::string::npos ? std::string::npos : e - b);
  if (e == std::string::npos) return s;
  std::stringstream rest(line.substr(e));
  for (std::string op; std::getline(rest, op, ',');) {
    const size_t ob = op.find_first_not_of(" \t"), oe = op.find_last_not_of(" \t\r");
    if (ob != std::string::npos) s.ops.push_back(op.substr(ob, oe - ob + 1));
  }
  return s;
}

// The simpler forms of one operand: without its sign/complement prefix, without its
// modifier suffix, without its swizzle or mask, and (sources only) the constant c0.
std::vector<std::string> simpler_operands(const std::string& op, bool source) {
  std::vector<std::string> out;
  std::string prefix;
  for (const char* p : {"1-", "-", "!"})
    if (op.rfind(p, 0) == 0 && prefix.empty()) prefix = p;
  if (!prefix.empty()) out.push_back(op.substr(prefix.size()));
  const size_t close = op.rfind(']');
  const size_t dot = op.find('.', close == std::string::npos ? 0 : close);
  const size_t under = op.find('_', close == std::string::npos ? 0 : close);
  if (under != std::string::npos) {
    std::string no_suffix = op.substr(0, under);
    if (dot != std::string::npos && dot > under) no_suffix += op.substr(dot);
    out.push_back(no_suffix);
  }
  if (dot != std::string::npos) out.push_back(op.substr(0, dot));
  // The constant keeps the sign or complement: a failure may need the modifier, not the
  // register. A second constant for a failure that needs two different values (lrp s0, s1, s2
  // with s1 = s2 hides s0).
  if (source && op != prefix + "c0") out.push_back(prefix + "c0");
  if (source && !prefix.empty() && op != "c0") out.push_back("c0");
  if (source && op != prefix + "c0" && op != prefix + "c1") out.push_back(prefix + "c1");
  return out;
}

// The simpler forms of a statement, one change each.
std::vector<std::string> simpler_statements(const std::string& line) {
  std::vector<std::string> out;
  Statement s = parse_statement(line);
  if (s.head.empty() || s.head.rfind("def", 0) == 0 || s.head.rfind("dcl", 0) == 0) return out;
  if (s.head[0] == '+') {
    Statement t = s;
    t.head.erase(0, 1);
    out.push_back(t.text());
  }
  static constexpr std::array<const char*, 9> kInstrMods = {"_sat", "_pp", "_x2", "_x4",      "_x8",
                                                            "_d2",  "_d4", "_d8", "_centroid"};
  for (const char* m : kInstrMods)
    if (size_t at = s.head.find(m); at != std::string::npos) {
      Statement t = s;
      t.head.erase(at, std::string(m).size());
      out.push_back(t.text());
    }
  for (size_t k = 0; k < s.ops.size(); ++k)
    for (const std::string& op : simpler_operands(s.ops[k], k > 0)) {
      Statement t = s;
      t.ops[k] = op;
      out.push_back(t.text());
    }
  return out;
}

// One pass over every line, keeping each simplification the predicate accepts.
bool simplify_operands(Lines& lines, const Predicate& fails) {
  bool changed = false;
  for (size_t i = 0; i < lines.size(); ++i)
    for (bool again = true; again;) {
      again = false;
      for (const std::string& candidate : simpler_statements(lines[i])) {
        Lines trial = lines;
        trial[i] = candidate;
        if (fails(join(trial))) {
          lines = std::move(trial);
          changed = again = true;
          break;
        }
      }
    }
  return changed;
}

} // namespace

std::string reduce_listing(const std::string& text, const Predicate& still_fails) {
  if (!still_fails(text)) return text;
  Lines lines = split(text);
  if (!still_fails(join(lines))) return text; // the predicate minds blank lines: leave it be
  for (int round = 0; round < 8; ++round) {
    lines = ddmin(std::move(lines), still_fails);
    if (!simplify_operands(lines, still_fails)) break;
  }
  return join(lines);
}

} // namespace tierlift::gen
