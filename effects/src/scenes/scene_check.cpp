#include "scene_check.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace tierlift::effects {
namespace {

std::string_view type_phrase(const Json& v) {
  switch (v.type()) {
  case Json::value_t::object: return "an object";
  case Json::value_t::array: return "an array";
  case Json::value_t::string: return "a string";
  case Json::value_t::boolean: return "a boolean";
  case Json::value_t::null: return "null";
  default: return "a number";
  }
}

// Levenshtein distance, for "did you mean" on a misspelt key (keys are short).
size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string unknown_key_message(std::string_view key, std::span<const std::string_view> keys) {
  std::string_view best;
  size_t best_distance = 3; // suggest only close matches
  for (std::string_view k : keys) {
    const size_t d = edit_distance(key, k);
    if (d < best_distance) best_distance = d, best = k;
  }
  if (!best.empty()) return fmt::format("unknown key \"{}\"; did you mean \"{}\"?", key, best);
  return fmt::format("unknown key \"{}\" (expected one of: {})", key, fmt::join(keys, ", "));
}

} // namespace

std::string FieldChecker::shown(const Json& v) {
  std::string s = v.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

TextSpan FieldChecker::span_of(const std::string& pointer, bool at_key) const {
  auto it = where_.at.find(pointer);
  if (it == where_.at.end()) return {};
  return at_key && it->second.key.length > 0 ? it->second.key : it->second.value;
}

void FieldChecker::error_at(size_t offset, size_t length, const std::string& message) {
  const LineCol lc = line_col(text_, offset);
  // The caret underlines the value on its first line only.
  const size_t line_end = text_.find('\n', std::min(offset, text_.size()));
  const size_t room = (line_end == std::string_view::npos ? text_.size() : line_end) -
                      std::min(offset, text_.size());
  ir::Diagnostic d;
  d.loc = {file_, lc.line, lc.col, uint32_t(std::clamp<size_t>(std::min(length, room), 1, 200))};
  d.message = message;
  found_.push_back(std::move(d));
}

void FieldChecker::error(const std::string& pointer, const std::string& message, bool at_key) {
  const TextSpan s = span_of(pointer, at_key);
  error_at(s.offset, s.length, pointer.empty() ? message : fmt::format("{}: {}", pointer, message));
}

void FieldChecker::move_to(ir::DiagnosticSink& sink) {
  std::stable_sort(found_.begin(), found_.end(), [](const auto& a, const auto& b) {
    return std::tie(a.loc.line, a.loc.col) < std::tie(b.loc.line, b.loc.col);
  });
  for (ir::Diagnostic& d : found_) sink.add(std::move(d));
  found_.clear();
}

void FieldChecker::type_error(const Json& v, const std::string& pointer,
                              std::string_view expected) {
  error(pointer, fmt::format("{} is {}; expected {}", shown(v), type_phrase(v), expected));
}

const Json* member(const Json& object, std::string_view key) {
  if (!object.is_object()) return nullptr;
  auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

bool FieldChecker::object(const Json& v, const std::string& pointer,
                          std::span<const std::string_view> keys,
                          std::span<const std::string_view> required) {
  if (!v.is_object()) {
    type_error(v, pointer, "an object");
    return false;
  }
  for (const auto& [key, value] : v.items()) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end())
      error(pointer + "/" + pointer_token(key), unknown_key_message(key, keys), true);
  }
  for (std::string_view key : required)
    if (!v.contains(key)) error(pointer, fmt::format("missing \"{}\"", key));
  return true;
}

std::optional<std::string> FieldChecker::string(const Json& v, const std::string& pointer) {
  if (v.is_string()) return v.get<std::string>();
  type_error(v, pointer, "a string");
  return std::nullopt;
}

std::optional<bool> FieldChecker::boolean(const Json& v, const std::string& pointer) {
  if (v.is_boolean()) return v.get<bool>();
  type_error(v, pointer, "true or false");
  return std::nullopt;
}

std::optional<int64_t> FieldChecker::integer(const Json& v, const std::string& pointer, int64_t lo,
                                             int64_t hi) {
  const std::string range = fmt::format("{}..{}", lo, hi);
  if (!v.is_number()) {
    type_error(v, pointer, "an integer in " + range);
    return std::nullopt;
  }
  const double d = v.get<double>();
  if (d != std::floor(d)) {
    error(pointer,
          fmt::format("{} is not a whole number; expected an integer in {}", shown(v), range));
    return std::nullopt;
  }
  if (d < double(lo) || d > double(hi)) { // compared in double: no out-of-range cast
    error(pointer, fmt::format("{} is outside {}", shown(v), range));
    return std::nullopt;
  }
  return static_cast<int64_t>(d);
}

bool FieldChecker::numbers(const Json& v, const std::string& pointer, NumberRange range,
                           std::span<double> out, std::string_view shape) {
  if (!v.is_array() || v.size() != out.size()) {
    error(pointer, fmt::format("{} is not {}", shown(v), shape));
    return false;
  }
  for (size_t i = 0; i < out.size(); ++i)
    if (auto x = number(v[i], fmt::format("{}/{}", pointer, i), range)) out[i] = *x;
  return true;
}

std::optional<double> FieldChecker::number(const Json& v, const std::string& pointer,
                                           NumberRange r) {
  if (!v.is_number()) {
    type_error(v, pointer, "a number");
    return std::nullopt;
  }
  const double d = v.get<double>();
  if (r.open_low && !(d > r.lo)) {
    error(pointer, fmt::format("{} must be > {} (and at most {})", shown(v), r.lo, r.hi));
    return std::nullopt;
  }
  if (!(d >= r.lo && d <= r.hi)) {
    error(pointer, r.open_low ? fmt::format("{} is above {}", shown(v), r.hi)
                              : fmt::format("{} is outside {}..{}", shown(v), r.lo, r.hi));
    return std::nullopt;
  }
  return d;
}

} // namespace tierlift::effects
