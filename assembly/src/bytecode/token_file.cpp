// The two file forms of a token stream: raw little-endian DWORDs, or the C array that
// headers and tests keep ("const DWORD g_ps[] = { 0xffff0200, ... };"). The C reader is a
// small scanner, not a C parser: it finds the first '{' outside comments, strings and
// preprocessor lines and reads numbers separated by commas up to the matching '}'.
#include <cctype>
#include <map>

#include <fmt/format.h>

#include "tierlift/assembly/bytecode.h"

namespace tierlift::assembly {
namespace {

bool is_text_byte(unsigned char c) {
  return c >= 0x20 || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

uint32_t le32(const std::string& b, size_t i) {
  auto u = [&](size_t k) { return uint32_t{static_cast<unsigned char>(b[i + k])}; };
  return u(0) | (u(1) << 8) | (u(2) << 16) | (u(3) << 24);
}

class ArrayScanner {
public:
  ArrayScanner(const std::string& text, ir::DiagnosticSink& diags, uint32_t file)
      : s_(text), diags_(diags), file_(file) {}

  std::optional<std::vector<uint32_t>> run() {
    size_t first = find_open_brace(0);
    if (first == std::string::npos) return read_values(std::string::npos); // a bare list
    // C++ around the array (engines keep precompiled shaders among their code): every brace
    // is a candidate, and the first array whose first value is a version token is the
    // shader. With none, the errors reported are those of the first array declaration.
    struct Stream {
      size_t open;
      std::string name;
      std::vector<uint32_t> tokens;
    };
    std::vector<Stream> streams;
    std::optional<std::vector<uint32_t>> first_without_version;
    size_t report_at = std::string::npos;
    for (size_t open = first; open != std::string::npos; open = find_open_brace(open + 1)) {
      std::string name = array_name();
      bool declared_array = decl_.find('[') != std::string::npos;
      if (report_at == std::string::npos && declared_array) report_at = open;
      trying_ = true; // a candidate that is no array fails silently
      auto tokens = read_values(open);
      trying_ = false;
      if (!tokens) continue;
      if ((tokens->front() >> 16) >= 0xFFFE)
        streams.push_back({open, name, std::move(*tokens)});
      else if (!first_without_version)
        first_without_version = std::move(tokens);
    }
    if (streams.empty()) {
      if (first_without_version) return first_without_version; // the reader names its fault
      return read_values(report_at == std::string::npos ? first : report_at);
    }
    if (streams.size() > 1) {
      const Stream& s = streams.front();
      diags_.note(loc_of(s.open), "token-file",
                  fmt::format("{} arrays in this file hold a token stream; the first, {}at "
                              "line {}, is the one read (keep one shader per file to read "
                              "another)",
                              streams.size(), s.name.empty() ? "" : "'" + s.name + "' ",
                              loc_of(s.open).line));
    }
    return std::move(streams.front().tokens);
  }

private:
  // The values of the array whose '{' is at `open` (npos: a bare list, read whole).
  std::optional<std::vector<uint32_t>> read_values(size_t open) {
    bool braced = open != std::string::npos;
    pos_ = braced ? open + 1 : 0;
    decl_ = braced ? decl_at_.at(open) : std::string();
    std::vector<uint64_t> values;
    for (;;) {
      skip_space();
      if (pos_ >= s_.size()) {
        if (braced) return fail(pos_, "missing '}' at the end of the array");
        break;
      }
      if (braced && s_[pos_] == '}') break;
      uint64_t v = 0;
      if (!number(v)) return std::nullopt;
      values.push_back(v);
      skip_space();
      if (pos_ < s_.size() && s_[pos_] == ',')
        ++pos_;
      else if (!(pos_ >= s_.size() || (braced && s_[pos_] == '}')))
        return fail(pos_, fmt::format("expected ',' or '}}' after a value, found {}", what()));
    }
    if (values.empty()) return fail(braced ? open : 0, "the array holds no values");
    return pack(values, braced ? open : 0);
  }

  // The name declared before the current '[': "g_ps" of "static const DWORD g_ps[] =".
  std::string array_name() const {
    size_t bracket = decl_.find('[');
    if (bracket == std::string::npos) return {};
    size_t end = bracket;
    while (end > 0 && std::isspace(static_cast<unsigned char>(decl_[end - 1]))) --end;
    size_t begin = end;
    while (begin > 0 &&
           (std::isalnum(static_cast<unsigned char>(decl_[begin - 1])) || decl_[begin - 1] == '_'))
      --begin;
    return decl_.substr(begin, end - begin);
  }

  ir::SourceLoc loc_of(size_t at) const {
    ir::SourceLoc loc{file_, 1, 1, 1};
    for (size_t i = 0; i < at && i < s_.size(); ++i) {
      if (s_[i] == '\n') {
        ++loc.line;
        loc.col = 1;
      } else {
        ++loc.col;
      }
    }
    return loc;
  }

  // While candidates are tried nothing is reported, and no position is worked out: that
  // walk from the start of the file, once per brace, would make a large source quadratic.
  std::nullopt_t fail(size_t at, const std::string& message) {
    if (!trying_) diags_.error(loc_of(at), "token-file", message);
    return std::nullopt;
  }

  std::string what() const {
    if (pos_ >= s_.size()) return "the end of the file";
    unsigned char c = static_cast<unsigned char>(s_[pos_]);
    if (c >= 0x21 && c < 0x7f) return fmt::format("'{}'", static_cast<char>(c));
    return fmt::format("byte 0x{:02X}", c);
  }

  bool at(const char* lit) const {
    return s_.compare(pos_, std::char_traits<char>::length(lit), lit) == 0;
  }

  // Skips one comment at pos_; false when there is none. An unterminated block comment
  // runs to the end of the file, as a compiler would report it anyway.
  bool skip_comment() {
    if (at("//")) {
      while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
      return true;
    }
    if (at("/*")) {
      size_t end = s_.find("*/", pos_ + 2);
      pos_ = end == std::string::npos ? s_.size() : end + 2;
      return true;
    }
    return false;
  }

  void skip_space() {
    while (pos_ < s_.size()) {
      if (std::isspace(static_cast<unsigned char>(s_[pos_])))
        ++pos_;
      else if (!skip_comment())
        return;
    }
  }

  // The first '{' that is code at or after `from`. Records the declaration text before it (comments
  // left out), which tells a BYTE array from a DWORD array.
  size_t find_open_brace(size_t from) {
    bool line_start = from == 0;
    pos_ = from;
    decl_.clear();
    while (pos_ < s_.size()) {
      char c = s_[pos_];
      if (skip_comment()) continue;
      if (c == '\n')
        line_start = true;
      else if (line_start && c == '#') { // preprocessor line, with continuations
        while (pos_ < s_.size() && s_[pos_] != '\n')
          pos_ += (s_[pos_] == '\\' && pos_ + 1 < s_.size()) ? 2 : 1;
        decl_.clear();
        continue;
      } else if (!std::isspace(static_cast<unsigned char>(c)))
        line_start = false;
      if (c == '"' || c == '\'') { // literals may hold braces
        for (++pos_; pos_ < s_.size() && s_[pos_] != c && s_[pos_] != '\n'; ++pos_)
          if (s_[pos_] == '\\') ++pos_;
        ++pos_;
        continue;
      }
      if (c == '{') {
        decl_at_[pos_] = decl_;
        return pos_;
      }
      if (c == ';' || c == '}')
        decl_.clear();
      else
        decl_ += c;
      ++pos_;
    }
    decl_.clear();
    return std::string::npos;
  }

  bool bytes_array() const {
    for (const char* w : {"BYTE", "char", "uint8_t", "UINT8", "byte"})
      if (decl_.find(w) != std::string::npos) return true;
    return false;
  }

  // C integer literal: 0x hex, 0 octal or decimal, then an optional u/l suffix.
  bool number(uint64_t& v) {
    size_t start = pos_;
    if (!std::isdigit(static_cast<unsigned char>(s_[pos_]))) {
      fail(pos_, fmt::format("expected a number, found {}", what()));
      return false;
    }
    int base = 10;
    if (at("0x") || at("0X")) {
      base = 16;
      pos_ += 2;
    } else if (s_[pos_] == '0') {
      base = 8;
    }
    size_t digits = 0;
    for (; pos_ < s_.size(); ++pos_, ++digits) {
      int c = std::tolower(static_cast<unsigned char>(s_[pos_]));
      int d = std::isdigit(c) ? c - '0' : (c >= 'a' && c <= 'f') ? c - 'a' + 10 : 99;
      if (d >= base) break;
      v = v * static_cast<uint64_t>(base) + static_cast<uint64_t>(d);
      if (v > 0xFFFFFFFFull) {
        fail(start, "value does not fit 32 bits");
        return false;
      }
    }
    if (base == 16 && digits == 0) {
      fail(start, "'0x' without hex digits");
      return false;
    }
    size_t suffix = pos_;
    int us = 0, ls = 0;
    for (; pos_ < s_.size(); ++pos_) {
      char c = s_[pos_];
      if (c == 'u' || c == 'U')
        ++us;
      else if (c == 'l' || c == 'L')
        ++ls;
      else
        break;
    }
    bool ident = pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) ||
                                      s_[pos_] == '_' || s_[pos_] == '.');
    if (us > 1 || ls > 2 || ident) {
      fail(suffix, fmt::format("malformed number '{}'",
                               s_.substr(start, std::min<size_t>(pos_ - start + 1, 40))));
      return false;
    }
    return true;
  }

  std::optional<std::vector<uint32_t>> pack(const std::vector<uint64_t>& values, size_t open) {
    std::vector<uint32_t> out;
    if (!bytes_array()) {
      out.assign(values.begin(), values.end());
      return out;
    }
    if (values.size() % 4 != 0)
      return fail(open, fmt::format("byte array of {} values is not a whole number of DWORDs",
                                    values.size()));
    for (size_t i = 0; i < values.size(); i += 4) {
      uint32_t t = 0;
      for (size_t k = 0; k < 4; ++k) {
        if (values[i + k] > 0xFF)
          return fail(open, fmt::format("byte array value {} (element {}) exceeds 255",
                                        values[i + k], i + k));
        t |= static_cast<uint32_t>(values[i + k]) << (8 * k);
      }
      out.push_back(t);
    }
    return out;
  }

  const std::string& s_;
  ir::DiagnosticSink& diags_;
  bool trying_ = false; // reading a candidate array: failures are not reported
  uint32_t file_;
  size_t pos_ = 0;
  std::string decl_;
  std::map<size_t, std::string> decl_at_; // the declaration text before each '{' found
};

} // namespace

std::optional<std::vector<uint32_t>> read_token_file(const std::string& bytes,
                                                     ir::DiagnosticSink& diags, uint32_t file) {
  bool whole_dwords = !bytes.empty() && bytes.size() % 4 == 0;
  size_t binary_at = bytes.size();
  for (size_t i = 0; i < bytes.size(); ++i)
    if (!is_text_byte(static_cast<unsigned char>(bytes[i]))) {
      binary_at = i;
      break;
    }
  // A version token (0xFFFE..../0xFFFF....) starts with bytes no text file has.
  uint32_t kind = bytes.size() >= 4 ? le32(bytes, 0) >> 16 : 0;
  if (whole_dwords && (kind == 0xFFFE || kind == 0xFFFF || binary_at < bytes.size())) {
    std::vector<uint32_t> out(bytes.size() / 4);
    for (size_t i = 0; i < out.size(); ++i) out[i] = le32(bytes, 4 * i);
    return out;
  }
  if (binary_at < bytes.size()) {
    diags.error({file, 0, 0, 0}, "token-file",
                fmt::format("neither a raw token stream ({} bytes is not a multiple of 4) nor "
                            "C text (byte 0x{:02X} at offset {})",
                            bytes.size(), static_cast<unsigned char>(bytes[binary_at]), binary_at));
    return std::nullopt;
  }
  return ArrayScanner(bytes, diags, file).run();
}

std::string tokens_to_bytes(const std::vector<uint32_t>& tokens) {
  std::string out;
  out.reserve(tokens.size() * 4);
  for (uint32_t t : tokens)
    for (int k = 0; k < 4; ++k) out += static_cast<char>((t >> (8 * k)) & 0xFF);
  return out;
}

} // namespace tierlift::assembly
