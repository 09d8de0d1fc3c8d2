// Statements: instructions (with modifiers and operand-count check against the opcode
// table), dcl in all its forms, and def/defi/defb with exact literal conversion.
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

#include <fmt/format.h>

#include "parser_impl.h"

namespace tierlift::assembly::detail {
namespace {

// Location of the part of a mnemonic token that starts `offset` bytes in.
ir::SourceLoc part_loc(const Token& mn, size_t offset, size_t len) {
  ir::SourceLoc loc = mn.loc;
  if (offset + len <= mn.text.size()) { // not when the token came out of a macro
    loc.col += static_cast<uint32_t>(offset);
    loc.length = static_cast<uint32_t>(len);
  }
  return loc;
}

// Calls f(part, offset) for every "_part" of "_a_b_c"; offset counts from the mnemonic start.
template <typename F> bool for_each_part(std::string_view mods, size_t base_len, F&& f) {
  size_t at = 0;
  while (at < mods.size()) {
    size_t next = mods.find('_', at + 1);
    if (next == std::string_view::npos) next = mods.size();
    if (!f(mods.substr(at + 1, next - at - 1), base_len + at + 1)) return false;
    at = next;
  }
  return true;
}

constexpr std::array<std::pair<std::string_view, ir::DeclUsage>, 14> kUsages = {{
    {"position", ir::DeclUsage::Position},
    {"blendweight", ir::DeclUsage::BlendWeight},
    {"blendindices", ir::DeclUsage::BlendIndices},
    {"normal", ir::DeclUsage::Normal},
    {"psize", ir::DeclUsage::PSize},
    {"texcoord", ir::DeclUsage::TexCoord},
    {"tangent", ir::DeclUsage::Tangent},
    {"binormal", ir::DeclUsage::Binormal},
    {"tessfactor", ir::DeclUsage::TessFactor},
    {"positiont", ir::DeclUsage::PositionT},
    {"color", ir::DeclUsage::Color},
    {"fog", ir::DeclUsage::Fog},
    {"depth", ir::DeclUsage::Depth},
    {"sample", ir::DeclUsage::Sample},
}};

} // namespace

bool Parser::expect_comma() {
  if (at_punct(",")) {
    advance();
    return true;
  }
  return fail(cur().loc, "syntax", fmt::format("expected ',', found {}", describe(cur())));
}

bool Parser::instr_mods(const Token& mn, std::string_view mods, ir::InstrMods& out) {
  size_t base_len = mn.text.size() - mods.size();
  bool shift_seen = false;
  return for_each_part(mods, base_len, [&](std::string_view m, size_t offset) {
    static constexpr std::pair<std::string_view, int8_t> shifts[] = {
        {"x2", 1}, {"x4", 2}, {"x8", 3}, {"d2", -1}, {"d4", -2}, {"d8", -3}};
    ir::SourceLoc loc = part_loc(mn, offset - 1, m.size() + 1);
    for (auto [name, shift] : shifts)
      if (m == name) {
        if (shift_seen) return fail(loc, "syntax", "more than one result shift (_x2/_d2/...)");
        shift_seen = true;
        out.shift = shift;
        return true;
      }
    bool* flag = m == "sat"        ? &out.sat
                 : m == "pp"       ? &out.pp
                 : m == "centroid" ? &out.centroid
                                   : nullptr;
    if (!flag)
      return fail(loc, "unknown-modifier", fmt::format("unknown instruction modifier '_{}'", m));
    if (*flag) return fail(loc, "syntax", fmt::format("modifier '_{}' given twice", m));
    *flag = true;
    return true;
  });
}

bool Parser::predicate(ir::SrcOperand& out) {
  ir::SourceLoc open = cur().loc;
  advance(); // '('
  Operand op;
  if (!operand(op)) return false;
  if (!at_punct(")"))
    return fail(cur().loc, "syntax",
                fmt::format("expected ')' after the predicate, found {}", describe(cur())));
  advance();
  if (op.file != ir::RegFile::Predicate || op.neg || op.comp || !op.modifier.empty() || op.rel)
    return fail(op.loc, "syntax", "a predicate is written (p0), (p0.x) or (!p0.x)");
  if (!to_src(op, out)) return false;
  out.loc = span_to_prev(open);
  return true;
}

bool Parser::instruction(const Token& mn, std::string_view base, std::string_view mods,
                         bool coissue, std::optional<ir::SrcOperand> pred) {
  const ir::OpInfo* info = ir::find_opcode(base, prog_.profile);
  if (!info && continued_)
    return fail(mn.loc, "syntax",
                fmt::format("unexpected '{}' after the operands (missing ','?)", mn.text));
  if (!info)
    return fail(part_loc(mn, 0, base.size()), "unknown-instruction",
                fmt::format("unknown instruction '{}'", mn.text.substr(0, base.size())));
  if (info->cls == ir::OpClass::Decl)
    return fail(mn.loc, "syntax", fmt::format("'{}' takes no modifiers and no '+'", base));
  ir::Instruction ins;
  ins.op = info->op;
  ins.coissue = coissue;
  ins.pred = std::move(pred);
  ins.loc = mn.loc;
  if (!instr_mods(mn, mods, ins.mods)) return false;

  std::vector<Operand> ops;
  if (!at_eol()) {
    while (true) {
      Operand op;
      if (!operand(op)) return false;
      ops.push_back(std::move(op));
      if (!at_punct(",")) break;
      advance();
    }
  }
  size_t expected = (info->has_dst ? 1u : 0u) + info->num_src;
  // An instruction this profile has in no form (texld in a vertex shader) is parsed as the
  // form its operands fit, if it has one: the validator then says the profile lacks it, which
  // helps more than an operand count that no form of the profile would have met either.
  if (ops.size() != expected && !ir::legal_in(*info, prog_.profile))
    for (const ir::OpInfo* r : ir::rows_for_mnemonic(base))
      if ((r->has_dst ? 1u : 0u) + r->num_src == ops.size()) {
        info = r;
        ins.op = r->op;
        expected = ops.size();
        break;
      }
  if (ops.size() != expected) {
    ir::SourceLoc loc = ops.size() > expected ? ops[expected].loc : mn.loc;
    return fail(loc, "operand-count",
                fmt::format("'{}' takes {} operand{}, found {}", info->mnemonic, expected,
                            expected == 1 ? "" : "s", ops.size()));
  }
  size_t k = 0;
  if (info->has_dst) {
    ins.dst.emplace();
    if (!to_dst(ops[k++], *ins.dst)) return false;
  }
  for (; k < ops.size(); ++k) {
    ir::SrcOperand src;
    if (!to_src(ops[k], src)) return false;
    // rcp and rsq written without a swizzle read their x component (docs/d3d9-rules.md §4.3: "for
    // rcp and rsq with no subscript, the assembler uses .x"). The IR holds that replicate
    // swizzle, so validator, interpreter, codegen and bytecode all agree on it. Other scalar
    // sources must name their component; the validator says so.
    if ((info->op == ir::Opcode::Rcp || info->op == ir::Opcode::Rsq) &&
        src.swizzle == ir::kIdentitySwizzle)
      src.swizzle = ir::replicate_swizzle(0);
    ins.src.push_back(src);
  }
  ins.seq = seq_++;
  prog_.code.push_back(std::move(ins));
  return true;
}

bool Parser::declaration(const Token& mn, std::string_view mods) {
  ir::Declaration decl;
  decl.loc = mn.loc;
  bool have_usage = false;
  bool ok = for_each_part(mods, 3, [&](std::string_view part, size_t offset) {
    ir::SourceLoc loc = part_loc(mn, offset - 1, part.size() + 1);
    if (part == "pp" || part == "centroid") {
      bool& flag = part == "pp" ? decl.mods.pp : decl.mods.centroid;
      if (flag) return fail(loc, "syntax", fmt::format("'_{}' given twice", part));
      flag = true;
      return true;
    }
    ir::SamplerType st = part == "2d"       ? ir::SamplerType::Tex2D
                         : part == "cube"   ? ir::SamplerType::Cube
                         : part == "volume" ? ir::SamplerType::Volume
                                            : ir::SamplerType::Unknown;
    if (st != ir::SamplerType::Unknown) {
      if (decl.sampler_type != ir::SamplerType::Unknown)
        return fail(loc, "syntax", "more than one sampler type");
      decl.sampler_type = st;
      return true;
    }
    size_t digits = part.size();
    while (digits > 0 && part[digits - 1] >= '0' && part[digits - 1] <= '9') --digits;
    std::string_view name = part.substr(0, digits), number = part.substr(digits);
    for (auto [uname, usage] : kUsages) {
      if (name != uname) continue;
      if (have_usage) return fail(loc, "syntax", "more than one usage in a declaration");
      unsigned idx = 0;
      if (!number.empty()) {
        auto [p, ec] = std::from_chars(number.data(), number.data() + number.size(), idx);
        if (ec != std::errc() || idx > 15)
          return fail(loc, "bad-number", fmt::format("usage index '{}' is not 0..15", number));
      }
      have_usage = true;
      decl.usage = usage;
      decl.usage_index = static_cast<uint8_t>(idx);
      return true;
    }
    return fail(loc, "unknown-modifier",
                fmt::format("unknown declaration usage or modifier '_{}'", part));
  });
  if (!ok) return false;
  if (at_eol())
    return fail(mn.loc, "operand-count", "'dcl' takes 1 operand (the declared register), found 0");
  Operand op;
  if (!operand(op) || !to_dst(op, decl.reg)) return false;
  if (decl.reg.rel) return fail(op.loc, "syntax", "a declaration names one register, not o[...]");
  if (!at_eol() && at_punct(","))
    return fail(cur().loc, "operand-count", "'dcl' takes 1 operand (the declared register)");
  decl.seq = seq_++;
  prog_.decls.push_back(decl);
  return true;
}

bool Parser::definition(const Token& mn, ir::Opcode op) {
  ir::ConstDef def;
  def.loc = mn.loc;
  def.file = op == ir::Opcode::Def    ? ir::RegFile::Const
             : op == ir::Opcode::DefI ? ir::RegFile::ConstInt
                                      : ir::RegFile::ConstBool;
  std::string_view letter = op == ir::Opcode::Def ? "c" : op == ir::Opcode::DefI ? "i" : "b";
  Operand reg;
  if (at_eol())
    return fail(mn.loc, "operand-count", fmt::format("'{}' needs a register and values", mn.text));
  if (!operand(reg)) return false;
  if (reg.file != def.file || reg.rel || reg.neg || reg.comp || reg.bnot || !reg.modifier.empty() ||
      reg.suffix)
    return fail(reg.loc, "syntax",
                fmt::format("'{}' defines a plain {}# register", lower(mn.text), letter));
  def.index = reg.index;
  int count = op == ir::Opcode::DefB ? 1 : 4;
  std::optional<ir::SourceLoc> missing_comma;
  for (int k = 0; k < count; ++k) {
    if (at_eol())
      return fail(mn.loc, "operand-count",
                  fmt::format("'{}' takes {} value{}, found {}", lower(mn.text), count,
                              count == 1 ? "" : "s", k));
    if (!def_comma(missing_comma)) return false;
    bool ok = op == ir::Opcode::Def    ? float_value(def.raw[k])
              : op == ir::Opcode::DefI ? int_value(def.raw[k])
                                       : bool_value(def.raw[k]);
    if (!ok) return false;
  }
  if (at_punct(","))
    return fail(cur().loc, "operand-count",
                fmt::format("'{}' takes {} value{}", lower(mn.text), count, count == 1 ? "" : "s"));
  if (missing_comma)
    diags_.warning(*missing_comma, "syntax",
                   fmt::format("'{}' without commas between its register and values: "
                               "shipped listings use the form and it is taken; the documented "
                               "syntax puts a comma before each value (--strict rejects it)",
                               lower(mn.text)));
  def.seq = seq_++;
  prog_.defs.push_back(def);
  return true;
}

// Valve's ps_1_1 listings write "def c0 0.5f 0.5f 0.5f 1.0f", and the shaders shipped: the
// values are still separate tokens, so nothing is ambiguous without the commas.
bool Parser::def_comma(std::optional<ir::SourceLoc>& missing) {
  if (at_punct(",")) {
    advance();
    return true;
  }
  if (strict_) return expect_comma();
  if (!missing) missing = cur().loc;
  return true;
}

// An optional leading "-" or "+" of a def value, taken; whether it was "-".
bool Parser::take_sign() {
  if (!at_punct("-") && !at_punct("+")) return false;
  const bool neg = cur().text == "-";
  advance();
  return neg;
}

// [+|-] number | inf | nan, read exactly as strtof reads it. "0x…" is an extension of ours:
// the raw bit pattern, so that the printer can write any NaN back losslessly.
bool Parser::float_value(uint32_t& raw) {
  const bool neg = take_sign();
  const Token& t = cur();
  std::string text = lower(t.text);
  if (t.kind == TokKind::Ident && (text == "inf" || text == "nan")) {
    raw = text == "inf" ? 0x7F800000u : 0x7FC00000u;
  } else if (t.kind == TokKind::Number && text.starts_with("0x")) {
    uint32_t bits = 0;
    auto [p, ec] = std::from_chars(text.data() + 2, text.data() + text.size(), bits, 16);
    if (ec != std::errc() || p != text.data() + text.size() || text.size() == 2)
      return fail(t.loc, "bad-number",
                  fmt::format("'{}' is not a 32-bit hexadecimal pattern", t.text));
    if (neg) return fail(t.loc, "bad-number", "a raw bit pattern cannot be negated");
    raw = bits;
  } else if (t.kind == TokKind::Number) {
    if (text.ends_with('f')) text.pop_back();
    bool chars_ok = !text.empty() && text.find_first_not_of("0123456789.e+-") == std::string::npos;
    errno = 0;
    char* end = nullptr;
    float f = chars_ok ? std::strtof(text.c_str(), &end) : 0.0f;
    if (!chars_ok || end != text.c_str() + text.size())
      return fail(t.loc, "bad-number", fmt::format("'{}' is not a number", t.text));
    if (errno == ERANGE && std::isinf(f))
      return fail(t.loc, "bad-number",
                  fmt::format("'{}' is out of range for a 32-bit float", t.text));
    raw = std::bit_cast<uint32_t>(f);
  } else {
    return fail(t.loc, "bad-number", fmt::format("expected a number, found {}", describe(t)));
  }
  if (neg) raw ^= 0x80000000u; // sign flip keeps -0 and is exact for every value
  advance();
  return true;
}

bool Parser::int_value(uint32_t& raw) {
  const bool neg = take_sign();
  const Token& t = cur();
  std::string text = lower(t.text);
  int base = 10;
  std::string_view digits = text;
  if (text.starts_with("0x")) base = 16, digits.remove_prefix(2);
  uint64_t v = 0;
  auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v, base);
  if (t.kind != TokKind::Number || digits.empty() || ec != std::errc() ||
      p != digits.data() + digits.size())
    return fail(t.loc, "bad-number", fmt::format("expected an integer, found {}", describe(t)));
  uint64_t limit = neg ? 0x80000000ull : base == 16 ? 0xFFFFFFFFull : 0x7FFFFFFFull;
  if (v > limit)
    return fail(t.loc, "bad-number",
                fmt::format("'{}' is out of range for a 32-bit integer", t.text));
  raw = static_cast<uint32_t>(neg ? (0 - v) : v);
  advance();
  return true;
}

bool Parser::bool_value(uint32_t& raw) {
  const Token& t = cur();
  std::string text = lower(t.text);
  if (text == "true" || text == "1")
    raw = 1;
  else if (text == "false" || text == "0")
    raw = 0;
  else
    return fail(t.loc, "bad-number", fmt::format("expected true or false, found {}", describe(t)));
  advance();
  return true;
}

} // namespace tierlift::assembly::detail
