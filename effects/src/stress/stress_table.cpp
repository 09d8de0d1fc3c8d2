// The stress rows as a text or markdown table (stress.h).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "tierlift/effects/report/stress.h"

namespace tierlift::effects {

std::string stress_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "+inf" : "-inf";
  return fmt::format("{:.6g}", v);
}

std::string stress_table(const std::vector<StressRow>& rows, bool markdown) {
  // The ways in order of first appearance.
  std::vector<std::string> ways;
  for (const StressRow& r : rows)
    for (const StressMeasure& m : r.measured)
      if (std::find(ways.begin(), ways.end(), m.way) == ways.end()) ways.push_back(m.way);
  std::vector<std::string> head = {"case", "format", "quantity", "expected", "±"};
  for (const std::string& w : ways) head.push_back(w);
  for (const char* h : {"agree", "verdict", "note"}) head.emplace_back(h);
  std::vector<std::vector<std::string>> cells;
  size_t pass = 0, fail = 0, error = 0;
  for (const StressRow& r : rows) {
    std::vector<std::string> c = {r.id, r.format, r.quantity, stress_number(r.expected),
                                  stress_number(r.tolerance)};
    for (const std::string& w : ways) {
      auto it = std::find_if(r.measured.begin(), r.measured.end(),
                             [&](const StressMeasure& m) { return m.way == w; });
      c.push_back(it == r.measured.end() ? "-" : stress_number(it->value));
    }
    c.push_back(r.ways_agree ? "yes" : "no");
    c.push_back(r.verdict);
    std::string note = r.error.empty() ? r.note : r.error;
    if (r.has_ideal && r.error.empty())
      note = fmt::format("ideal {}{}{}", stress_number(r.ideal), note.empty() ? "" : "; ", note);
    c.push_back(note);
    cells.push_back(std::move(c));
    (r.verdict == "PASS" ? pass : r.verdict == "FAIL" ? fail : error)++;
  }
  std::string out;
  if (markdown) {
    auto line = [&](const std::vector<std::string>& c) {
      out += "|";
      for (const std::string& s : c) out += " " + s + " |";
      out += "\n";
    };
    line(head);
    out += "|";
    for (size_t i = 0; i < head.size(); ++i) out += "---|";
    out += "\n";
    for (const auto& c : cells) line(c);
  } else {
    // Every column but the last (the note) padded to its widest cell (in bytes: the cells
    // are ASCII apart from a few symbols in the quantity column).
    std::vector<size_t> width(head.size(), 0);
    for (size_t i = 0; i + 1 < head.size(); ++i) {
      width[i] = head[i].size();
      for (const auto& c : cells) width[i] = std::max(width[i], c[i].size());
    }
    auto line = [&](const std::vector<std::string>& c) {
      std::string l;
      for (size_t i = 0; i < c.size(); ++i)
        l += i + 1 < c.size() ? fmt::format("{:<{}}  ", c[i], width[i]) : c[i];
      while (!l.empty() && l.back() == ' ') l.pop_back();
      out += l + "\n";
    };
    line(head);
    for (const auto& c : cells) line(c);
  }
  out += fmt::format("{}{} rows: {} PASS, {} FAIL, {} ERROR\n", markdown ? "\n" : "", rows.size(),
                     pass, fail, error);
  return out;
}

} // namespace tierlift::effects
