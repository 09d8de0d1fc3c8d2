// The stress catalogue of `tierlift report --stress`: stiff and extreme glow cases built in
// code, each run on every way (cpu, vulkan, analytic), each with a closed form or a bound for
// what must come out. A row is one quantity of one case: what each way measured, what the
// closed form expects (per way where a device is documented to differ: lavapipe flushes
// denormals), the tolerance and where it comes from, whether the ways agree with each other,
// and a verdict. docs/stress.md lists the catalogue and its closed forms.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "tierlift/effects/graph/device.h"
#include "tierlift/ir/result.h"

namespace tierlift::effects {

struct StressMeasure {
  std::string way; // "cpu", "vulkan", "analytic"
  double value = 0;
  // Where the case asks where something lands (non-finite texels): one entry per texel of
  // the measured texture, 1 where it holds. The ways agree when their masks are equal.
  std::vector<uint8_t> mask;
};

struct StressRow {
  std::string id;       // "hdr.6e4.rgba16f", unique
  std::string regime;   // "hdr", "non-finite", "denormal", "sigma", "downsample", …
  std::string format;   // "rgba8", "rgba16f", "rgba32f"
  std::string quantity; // what is measured, in words
  double expected = 0;  // the closed form (or the store rule's recurrence, see `bound`)
  double tolerance = 0; // |measured − expected| ≤ tolerance (NaN matches NaN, ±inf itself)
  // Ways whose documented behaviour differs from `expected` (lavapipe's denormal flush):
  // either value passes for them.
  std::map<std::string, double, std::less<>> also_expected;
  std::string bound;      // where expected and tolerance come from
  double ideal = 0;       // the value with no rounding at all (for the drift column)
  bool has_ideal = false; // `ideal` is meaningful for this row
  std::vector<StressMeasure> measured;
  std::string note;        // what the row shows (e.g. "RGBA8: the decay stalls at 49/255")
  std::string error;       // a way failed to run: verdict ERROR
  bool ways_agree = false; // set by judge_stress_row
  bool pass = false;       // set by judge_stress_row
  std::string verdict;     // "PASS", "FAIL" or "ERROR"
};

// Sets ways_agree, pass and verdict from the row's measured values, expected value and
// tolerance. PASS: no error, every way within tolerance of `expected` (or of its entry in
// also_expected), and the ways agree (equal masks where masks were measured, else values
// within the tolerance of each other).
void judge_stress_row(StressRow& row);

// A fresh device for a way's name ("cpu", "vulkan", "analytic"); nullptr when that way is
// not available.
using StressDeviceFactory = std::function<std::unique_ptr<PassDevice>(const std::string& way)>;

struct StressOptions {
  std::vector<std::string> ways = {"cpu", "vulkan", "analytic"};
  StressDeviceFactory make_device;
  // Called before each case runs (its id and how many cases there are), for progress lines.
  std::function<void(const std::string& case_id, size_t index, size_t count)> progress;
};

// Every case of the catalogue, in order, each row judged.
std::vector<StressRow> run_stress_catalogue(const StressOptions& options);

// The case ids of the catalogue (a case gives one or more rows), without running anything.
std::vector<std::string> stress_case_ids();

// One case by id (rows judged); fails (rule "usage") for an unknown id.
ir::Result<std::vector<StressRow>> run_stress_case(const std::string& id,
                                                   const StressOptions& options);

} // namespace tierlift::effects

namespace tierlift::effects {

// The rows as a table: columns case, format, quantity, expected ± tolerance, one column per
// way measured, agree, verdict, note. `markdown`: a GitHub table (docs, report.md), else
// aligned plain text. A closing line counts PASS / FAIL / ERROR.
std::string stress_table(const std::vector<StressRow>& rows, bool markdown);

// A value as the tables print it: 6 significant digits, "nan", "+inf", "-inf".
std::string stress_number(double v);

} // namespace tierlift::effects
