// Typed reads of a scene's JSON values, each failure a diagnostic at the value (or key) its
// JSON pointer names: "FILE:LINE:COL: error: /glow/downsample: 9 is outside 1..4".
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "json_locate.h"
#include "tierlift/ir/diagnostic.h"

namespace tierlift::effects {

using Json = nlohmann::json;

// Numbers a field accepts: lo..hi, or lo < v ≤ hi with `open_low`.
struct NumberRange {
  double lo = 0, hi = 0;
  bool open_low = false;
};

// The member `key` of an object, or null (a missing key, or `object` not an object). Reading
// a missing key with const operator[] is undefined behaviour in nlohmann, so every optional
// or required member is read through this.
const Json* member(const Json& object, std::string_view key);

class FieldChecker {
public:
  FieldChecker(std::string_view text, uint32_t file, const JsonLocations& where)
      : text_(text), file_(file), where_(where) {}

  // "POINTER: message" at the pointer's value, or at its key (unknown keys).
  void error(const std::string& pointer, const std::string& message, bool at_key = false);
  // Without a pointer prefix (the document as a whole; JSON syntax).
  void error_at(size_t offset, size_t length, const std::string& message);
  bool failed() const { return !found_.empty(); }
  // The diagnostics in the order of the text (nlohmann's objects iterate keys sorted).
  void move_to(ir::DiagnosticSink& sink);

  // An object whose keys are all in `keys` (each other key is an error); false when `v` is
  // not an object. `required` keys must be present.
  bool object(const Json& v, const std::string& pointer, std::span<const std::string_view> keys,
              std::span<const std::string_view> required = {});
  std::optional<std::string> string(const Json& v, const std::string& pointer);
  std::optional<bool> boolean(const Json& v, const std::string& pointer);
  // Whole numbers (2.0 counts, as in JSON Schema) in lo..hi.
  std::optional<int64_t> integer(const Json& v, const std::string& pointer, int64_t lo, int64_t hi);
  std::optional<double> number(const Json& v, const std::string& pointer, NumberRange range);
  // An array of exactly out.size() numbers in `range`, each read into out[i] (one that is
  // not in range is an error at "POINTER/i" and leaves out[i] as it was); any other value is
  // the error "… is not SHAPE" (e.g. "[x, y] (texture coordinates, 0..1)"). False then.
  bool numbers(const Json& v, const std::string& pointer, NumberRange range, std::span<double> out,
               std::string_view shape);

  // The JSON text of a value for a message, cut at 40 characters.
  static std::string shown(const Json& v);

private:
  TextSpan span_of(const std::string& pointer, bool at_key) const;
  void type_error(const Json& v, const std::string& pointer, std::string_view expected);

  std::string_view text_;
  uint32_t file_ = 0;
  const JsonLocations& where_;
  std::vector<ir::Diagnostic> found_;
};

} // namespace tierlift::effects
