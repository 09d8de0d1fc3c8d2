#include "json_locate.h"

#include <cmath>
#include <cstdlib>
#include <set>

#include <nlohmann/json.hpp>

namespace tierlift::effects {
namespace {

constexpr int kMaxDepth = 64;

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

bool is_number_char(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

bool is_letter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// A key's text with its quotes → the key, escapes resolved (nlohmann reads the string).
std::string unquote(std::string_view quoted) {
  try {
    nlohmann::json j = nlohmann::json::parse(quoted);
    if (j.is_string()) return j.get<std::string>();
  } catch (const nlohmann::json::exception&) {
  }
  return std::string(quoted.size() >= 2 ? quoted.substr(1, quoted.size() - 2) : quoted);
}

class Locator {
public:
  Locator(std::string_view text, JsonLocations& out) : t_(text), out_(out) {}

  void run() {
    if (t_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3; // nlohmann skips a UTF-8 BOM too
    value("", {}, 0);
  }

private:
  void skip_space() {
    while (i_ < t_.size() && is_space(t_[i_])) ++i_;
  }

  bool at(char c) {
    skip_space();
    return i_ < t_.size() && t_[i_] == c;
  }

  // At the opening quote; moves past the closing one.
  bool string() {
    ++i_;
    while (i_ < t_.size()) {
      if (t_[i_] == '\\')
        i_ += 2;
      else if (t_[i_++] == '"')
        return true;
    }
    i_ = t_.size();
    return false;
  }

  bool scalar() {
    const size_t start = i_;
    while (i_ < t_.size() && (is_number_char(t_[i_]) || is_letter(t_[i_]))) ++i_;
    if (i_ == start) return false;
    const char first = t_[start];
    if (first == '-' || (first >= '0' && first <= '9')) {
      const std::string number(t_.substr(start, i_ - start));
      if (std::isinf(std::strtod(number.c_str(), nullptr)) && !out_.number_overflow)
        out_.number_overflow = TextSpan{start, i_ - start};
    }
    return true;
  }

  bool object(const std::string& pointer, int depth) {
    ++i_; // '{'
    if (at('}')) return ++i_, true;
    std::set<std::string> seen;
    for (;;) {
      if (!at('"')) return false;
      const size_t key_start = i_;
      if (!string()) return false;
      const TextSpan key{key_start, i_ - key_start};
      const std::string name = unquote(t_.substr(key.offset, key.length));
      const std::string member = pointer + "/" + pointer_token(name);
      if (!seen.insert(name).second) out_.duplicate_keys.emplace_back(member, key);
      if (!at(':')) return false;
      ++i_;
      if (!value(member, key, depth + 1)) return false;
      if (at(',')) {
        ++i_;
        continue;
      }
      if (at('}')) return ++i_, true;
      return false;
    }
  }

  bool array(const std::string& pointer, int depth) {
    ++i_; // '['
    if (at(']')) return ++i_, true;
    for (size_t n = 0;; ++n) {
      if (!value(pointer + "/" + std::to_string(n), {}, depth + 1)) return false;
      if (at(',')) {
        ++i_;
        continue;
      }
      if (at(']')) return ++i_, true;
      return false;
    }
  }

  bool value(const std::string& pointer, TextSpan key, int depth) {
    if (depth > kMaxDepth) return false;
    skip_space();
    if (i_ >= t_.size()) return false;
    const size_t start = i_;
    bool ok = false;
    switch (t_[i_]) {
    case '{': ok = object(pointer, depth); break;
    case '[': ok = array(pointer, depth); break;
    case '"': ok = string(); break;
    default: ok = scalar(); break;
    }
    out_.at[pointer] = JsonPlace{key, TextSpan{start, i_ - start}};
    return ok;
  }

  std::string_view t_;
  JsonLocations& out_;
  size_t i_ = 0;
};

} // namespace

JsonLocations locate_json(std::string_view text) {
  JsonLocations out;
  Locator(text, out).run();
  return out;
}

std::optional<size_t> nesting_beyond(std::string_view text, int limit) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::nullopt;
}

LineCol line_col(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  LineCol lc;
  size_t line_start = 0;
  for (size_t i = 0; i < offset; ++i)
    if (text[i] == '\n') {
      ++lc.line;
      line_start = i + 1;
    }
  lc.col = static_cast<uint32_t>(offset - line_start + 1);
  return lc;
}

std::string pointer_token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

} // namespace tierlift::effects
