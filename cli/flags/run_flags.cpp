// Parsers for the values of `tierlift run`'s flags into the pass settings (tierlift/pass/
// setup.h). Each gives a value or a one-line reason.
#include <bit>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <string>

#include "run_flags.h"
#include "tierlift/assembly/constant_table.h"

namespace tierlift::cli {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool parse_u32(std::string_view s, uint32_t& out) {
  s = trim(s);
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && p == s.data() + s.size() && !s.empty();
}

// What `def` takes (the parser's float_value), so that a value can move between a listing
// and the command line: [+|-] decimal with an optional 'f' suffix, read by strtof (a value
// that underflows to a denormal or zero is kept, one that overflows is refused), inf, nan,
// or 0x… as the raw 32-bit pattern (not negatable).
bool parse_float(std::string_view s, float& out) {
  s = trim(s);
  bool neg = false;
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
    neg = s.front() == '-';
    s.remove_prefix(1);
  }
  std::string text(s);
  for (char& ch : text) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  uint32_t raw = 0;
  if (text == "inf" || text == "nan") {
    raw = text == "inf" ? 0x7F800000u : 0x7FC00000u;
  } else if (text.starts_with("0x")) {
    auto [p, ec] = std::from_chars(text.data() + 2, text.data() + text.size(), raw, 16);
    if (neg || text.size() == 2 || ec != std::errc() || p != text.data() + text.size())
      return false;
  } else {
    if (text.ends_with('f')) text.pop_back();
    if (text.empty() || text.find_first_not_of("0123456789.e+-") != std::string::npos) return false;
    errno = 0;
    char* end = nullptr;
    float f = std::strtof(text.c_str(), &end);
    if (end != text.c_str() + text.size() || (errno == ERANGE && std::isinf(f))) return false;
    raw = std::bit_cast<uint32_t>(f);
  }
  if (neg) raw ^= 0x80000000u;
  out = std::bit_cast<float>(raw);
  return true;
}

bool parse_i32(std::string_view s, int32_t& out) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && p == s.data() + s.size() && !s.empty();
}

// Splits "a,b,c,d" into exactly n fields.
bool split_fields(std::string_view s, size_t n, std::vector<std::string_view>& out) {
  out.clear();
  size_t start = 0;
  for (;;) {
    size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string_view::npos ? s.npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out.size() == n;
}

bool parse_vec4(std::string_view s, Vec4& v) {
  std::vector<std::string_view> f;
  if (!split_fields(s, 4, f)) return false;
  for (int i = 0; i < 4; ++i)
    if (!parse_float(f[i], v[i])) return false;
  return true;
}

// The field of "a,b,c,d" that is a decimal number beyond float's range (strtof overflows
// it to inf, which parse_float refuses), or empty: a message that says so reads better than
// "needs four numbers" for a value that is a number.
std::string out_of_float_range(std::string_view s) {
  std::vector<std::string_view> fields;
  split_fields(s, 0, fields);
  for (std::string_view field : fields) {
    std::string text(trim(field));
    if (!text.empty() && (text.back() == 'f' || text.back() == 'F')) text.pop_back();
    if (text.empty() || text.find_first_not_of("0123456789.eE+-") != std::string::npos) continue;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() + text.size() && std::isfinite(v) && std::fabs(v) > FLT_MAX)
      return text;
  }
  return {};
}

// "needs four numbers" or, for a number beyond float's range, that.
std::string vec4_problem(std::string_view value, std::string_view needs) {
  if (std::string big = out_of_float_range(value); !big.empty())
    return fmt::format("{} is out of float range (largest {:g})", big, FLT_MAX);
  return std::string(needs);
}

// "NAME=VALUE" → (NAME, VALUE).
bool split_assignment(std::string_view text, std::string_view& name, std::string_view& value) {
  size_t eq = text.find('=');
  if (eq == std::string_view::npos) return false;
  name = trim(text.substr(0, eq));
  value = trim(text.substr(eq + 1));
  return true;
}

// "c12" with prefix letter `letter` → 12, below `limit`.
bool parse_reg(std::string_view name, std::string_view prefix, uint32_t limit, uint32_t& index) {
  if (name.size() <= prefix.size() || name.substr(0, prefix.size()) != prefix) return false;
  return parse_u32(name.substr(prefix.size()), index) && index < limit;
}

constexpr uint32_t kMaxConstRegisters = 4096;

// A flag's value the parser refuses: one error naming the flag and the value, which the CLI
// reports with rule "usage" and exit 2.
ir::Failure usage(std::string message) {
  return ir::fail("", "usage", std::move(message));
}

} // namespace

namespace {

// "[vs:|ps:]…": the stages a setting names, the prefix taken off `body` (the one place it is
// read).
StageMask take_stage_prefix(std::string_view& body) {
  if (body.starts_with("vs:")) {
    body.remove_prefix(3);
    return StageMask::Vertex;
  }
  if (body.starts_with("ps:")) {
    body.remove_prefix(3);
    return StageMask::Pixel;
  }
  return StageMask::Both;
}

// A register name — c, i or b and digits — and its file and index (the index not yet
// checked against the file's size); nullopt for any other name (a CTAB name, then).
struct RegisterName {
  ir::RegFile file;
  uint32_t index = 0;
};
std::optional<RegisterName> register_name(std::string_view name) {
  if (name.size() < 2) return std::nullopt;
  ir::RegFile file;
  switch (name[0]) {
  case 'c': file = ir::RegFile::Const; break;
  case 'i': file = ir::RegFile::ConstInt; break;
  case 'b': file = ir::RegFile::ConstBool; break;
  default: return std::nullopt;
  }
  for (char ch : name.substr(1))
    if (!std::isdigit(static_cast<unsigned char>(ch))) return std::nullopt;
  uint32_t index = 0;
  if (!parse_u32(name.substr(1), index)) index = UINT32_MAX; // too many digits: out of range
  return RegisterName{file, index};
}

// The value of one register `reg`, typed by its file: four floats (c#), four integers (i#)
// or a boolean (b#). `text` is the whole setting, for messages.
ir::Result<ConstSetting> register_value(StageMask stage, RegisterName reg, std::string_view value,
                                        std::string_view text) {
  ConstSetting c;
  c.stage = stage;
  c.file = reg.file;
  c.index = reg.index;
  const uint32_t limit = reg.file == ir::RegFile::Const ? kMaxConstRegisters : 16;
  if (reg.index >= limit)
    return usage(fmt::format("--const '{}': register must be c0..c{}, i0..i15 or b0..b15", text,
                             kMaxConstRegisters - 1));
  if (reg.file == ir::RegFile::Const) {
    if (parse_vec4(value, c.f)) return c;
    return usage(fmt::format("--const '{}': {}", text,
                             vec4_problem(value, "c# needs four numbers x,y,z,w")));
  }
  if (reg.file == ir::RegFile::ConstInt) {
    std::vector<std::string_view> f;
    bool ok = split_fields(value, 4, f);
    for (int k = 0; ok && k < 4; ++k) ok = parse_i32(f[k], c.i[k]);
    if (ok) return c;
    return usage(fmt::format("--const '{}': i# needs four integers a,b,c,d", text));
  }
  if (value == "true" || value == "1" || value == "false" || value == "0") {
    c.b = value == "true" || value == "1";
    return c;
  }
  return usage(fmt::format("--const '{}': b# is true or false", text));
}

// The registers a constant named by a constant table covers: a boolean takes one value, a
// float or integer constant 4 per register in register order (a matrix or an array: up to
// 4·count), a sampler none (it is bound with --texture).
ir::Result<std::vector<ConstSetting>> named_value(StageMask stage, const assembly::NamedConstant& c,
                                                  std::string_view value, std::string_view text) {
  auto fail = [&](std::string why) {
    return usage(fmt::format("--const '{}': {}", text, std::move(why)));
  };
  std::vector<std::string_view> values;
  split_fields(value, 0, values);
  std::vector<ConstSetting> out;
  if (c.set == assembly::ConstantSet::Sampler)
    return fail(
        fmt::format("'{}' is a sampler ({}); bind it with --texture", c.name, c.registers()));
  if (c.set == assembly::ConstantSet::Bool) {
    if (values.size() != 1)
      return fail(fmt::format("'{}' ({}) takes one value, true or false", c.name, c.registers()));
    ir::Result<ConstSetting> b =
        register_value(stage, {ir::RegFile::ConstBool, c.index}, value, text);
    if (!b) return b.failure();
    out.push_back(*b);
    return out;
  }
  if (values.size() % 4 != 0 || values.size() > 4 * size_t{c.count})
    return fail(fmt::format("'{}' ({}, {}) takes 4 numbers per register, at most {}; got {}",
                            c.name, c.registers(), c.type.empty() ? "?" : c.type, 4 * c.count,
                            values.size()));
  const ir::RegFile file =
      c.set == assembly::ConstantSet::Int4 ? ir::RegFile::ConstInt : ir::RegFile::Const;
  for (uint32_t r = 0; r < values.size() / 4; ++r) {
    const std::string_view* v = &values[4 * r];
    const std::string four = fmt::format("{},{},{},{}", v[0], v[1], v[2], v[3]);
    ir::Result<ConstSetting> s = register_value(stage, {file, c.index + r}, four, text);
    if (!s) return s.failure();
    out.push_back(*s);
  }
  return out;
}

} // namespace

ir::Result<std::vector<ConstSetting>> parse_const_assignment(std::string_view text,
                                                             const assembly::ConstantTable* vs,
                                                             const assembly::ConstantTable* ps) {
  std::string_view body = trim(text);
  const StageMask stage = take_stage_prefix(body);
  std::string_view name, value;
  if (!split_assignment(body, name, value))
    return usage(fmt::format(
        "--const '{}': expected [vs:|ps:]cN=x,y,z,w, iN=a,b,c,d or bN=true|false", text));
  if (std::optional<RegisterName> reg = register_name(name)) {
    ir::Result<ConstSetting> c = register_value(stage, *reg, value, text);
    if (!c) return c.failure();
    return std::vector<ConstSetting>{*c};
  }
  std::vector<ConstSetting> out;
  for (auto [mask, table] : {std::pair{StageMask::Vertex, vs}, {StageMask::Pixel, ps}}) {
    const assembly::NamedConstant* c =
        table && (stage == StageMask::Both || stage == mask) ? table->find(name) : nullptr;
    if (!c) continue;
    ir::Result<std::vector<ConstSetting>> regs = named_value(mask, *c, value, text);
    if (!regs) return regs.failure();
    out.insert(out.end(), regs->begin(), regs->end());
  }
  if (out.empty())
    return usage(fmt::format("--const '{}': '{}' is neither a register (cN, iN, bN) nor a "
                             "constant named in the listings' constant tables (CTAB){}",
                             text, name, vs || ps ? "" : "; these listings carry none"));
  return out;
}

ir::Result<std::vector<ConstSetting>> parse_const_assignments(const std::vector<std::string>& texts,
                                                              const assembly::ConstantTable* vs,
                                                              const assembly::ConstantTable* ps) {
  std::vector<ConstSetting> out;
  for (const std::string& text : texts) {
    ir::Result<std::vector<ConstSetting>> one = parse_const_assignment(text, vs, ps);
    if (!one) return one.failure();
    out.insert(out.end(), one->begin(), one->end());
  }
  return out;
}

ir::Result<ConstSetting> parse_const_setting(std::string_view text) {
  ir::Result<std::vector<ConstSetting>> one = parse_const_assignment(text, nullptr, nullptr);
  if (!one) return one.failure();
  return one->front();
}

ir::Result<RegisterSetting> parse_input_setting(std::string_view text) {
  RegisterSetting r;
  std::string_view name, value;
  bool named = split_assignment(text, name, value);
  if (named && parse_reg(name, "v", 2, r.index))
    r.file = ir::RegFile::Input;
  else if (named && parse_reg(name, "t", 8, r.index))
    r.file = ir::RegFile::Texture;
  else {
    return usage(fmt::format("--input '{}': expected v0|v1|t0..t7=x,y,z,w", text));
  }
  if (parse_vec4(value, r.value)) return r;
  return usage(fmt::format("--input '{}': {}", text,
                           vec4_problem(value, "the value needs four numbers x,y,z,w")));
}

ir::Result<RegisterSetting> parse_attr_setting(std::string_view text) {
  RegisterSetting r;
  std::string_view name, value;
  if (!split_assignment(text, name, value) || !parse_reg(name, "v", 16, r.index)) {
    return usage(fmt::format("--attr '{}': expected v0..v15=x,y,z,w or v0..v15=quad-uv", text));
  }
  if (value == "quad-uv") {
    r.quad_uv = true;
    return r;
  }
  if (parse_vec4(value, r.value)) return r;
  return usage(fmt::format("--attr '{}': {}", text,
                           vec4_problem(value, "the value needs four numbers x,y,z,w or quad-uv")));
}

// "[vs:|ps:]sN=SOURCE", the prefix read as --const reads it; without one, the pixel stage's
// sN (what every texture was before vertex texture fetch). vs:sN is the vertex stage's
// sampler N, pass::kVertexSampler0 + N (N 0..3).
ir::Result<TextureSetting> parse_texture_setting(std::string_view text) {
  TextureSetting t;
  std::string_view body = text, name, value;
  const bool vertex = take_stage_prefix(body) == StageMask::Vertex;
  const uint32_t count = vertex ? pass::kMaxVertexSamplers : kMaxSamplers;
  if (!split_assignment(body, name, value) || !parse_reg(name, "s", count, t.sampler) ||
      value.empty()) {
    return usage(
        fmt::format("--texture '{}': expected [ps:]sN=FILE.png|FILE.pfm|builtin:NAME[:WxH] "
                    "(N 0..15) or vs:sN=... (the vertex stage's samplers, N 0..3)",
                    text));
  }
  if (vertex) t.sampler += pass::kVertexSampler0;
  t.source = std::string(value);
  return t;
}

ir::Result<pass::BumpSetting> parse_bump_setting(std::string_view text) {
  pass::BumpSetting b;
  std::string_view name, value;
  // Texture stages of ps_1_x: 0..7 (ps_1_4 has 6, the rest 4; the validator's business).
  if (!split_assignment(text, name, value) || !parse_u32(name, b.stage) || b.stage >= 8)
    return usage(fmt::format("--bump-matrix '{}': expected STAGE=m00,m01,m10,m11 with STAGE "
                             "0..7",
                             text));
  Vec4 m{};
  if (!parse_vec4(value, m))
    return usage(fmt::format("--bump-matrix '{}': {}", text,
                             vec4_problem(value, "the matrix needs four numbers m00,m01,m10,m11")));
  b.matrix = m;
  return b;
}

ir::Result<ProbePoint> parse_probe(std::string_view text) {
  std::vector<std::string_view> f;
  ProbePoint p;
  if (split_fields(text, 2, f) && parse_u32(f[0], p.x) && parse_u32(f[1], p.y)) return p;
  return usage(fmt::format("--probe '{}': expected X,Y (non-negative integers)", text));
}

ir::Result<std::array<uint32_t, 2>> parse_size(std::string_view text) {
  size_t x = text.find_first_of("xX");
  uint32_t w = 0, h = 0;
  if (x == std::string_view::npos || !parse_u32(text.substr(0, x), w) ||
      !parse_u32(text.substr(x + 1), h)) {
    return usage(fmt::format("--size '{}': expected WxH, e.g. 256x256", text));
  }
  if (!img::valid_size(w, h)) {
    return usage(
        fmt::format("--size '{}': width and height must be 1..{}", text, img::kMaxDimension));
  }
  return std::array<uint32_t, 2>{w, h};
}

std::optional<Filter> parse_filter(std::string_view text) {
  if (text == "point") return Filter::Point;
  if (text == "linear") return Filter::Linear;
  return std::nullopt;
}

std::optional<pass::MipFilter> parse_mip_filter(std::string_view text) {
  if (text == "none") return pass::MipFilter::None;
  if (text == "point") return pass::MipFilter::Point;
  if (text == "linear") return pass::MipFilter::Linear;
  return std::nullopt;
}

std::optional<uint32_t> parse_level_count(std::string_view text) {
  uint32_t n = 0;
  if (text.empty() || text.size() > 2) return std::nullopt;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    n = n * 10 + static_cast<uint32_t>(c - '0');
  }
  if (n < 1 || n > 32) return std::nullopt;
  return n;
}

std::optional<AddressMode> parse_address(std::string_view text) {
  if (text == "clamp") return AddressMode::Clamp;
  if (text == "wrap") return AddressMode::Wrap;
  if (text == "mirror") return AddressMode::Mirror;
  if (text == "border") return AddressMode::Border;
  return std::nullopt;
}

std::optional<ir::PixelCenter> parse_pixel_center(std::string_view text) {
  if (text == "d3d9") return ir::PixelCenter::D3D9;
  if (text == "modern") return ir::PixelCenter::Modern;
  return std::nullopt;
}

} // namespace tierlift::cli
