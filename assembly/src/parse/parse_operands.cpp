// Operands: [-|1-|!]reg[_mod][.swizzle|.mask] with every relative-addressing spelling the
// D3DX assembler takes (c[a0.x + 4], c4[a0.x], c[4 + a0.x], c[2 + a0.x + 12], c4[2], c[aL]).
#include <algorithm>
#include <charconv>

#include <fmt/format.h>

#include "parser_impl.h"
#include "tierlift/ir/source_modifiers.h"

namespace tierlift::assembly::detail {
namespace {

// x/r → 0, y/g → 1, z/b → 2, w/a → 3; -1 for anything else.
int component_of(char c) {
  switch (c) {
  case 'x':
  case 'r': return 0;
  case 'y':
  case 'g': return 1;
  case 'z':
  case 'b': return 2;
  case 'w':
  case 'a': return 3;
  default: return -1;
  }
}

struct NamedReg {
  std::string_view prefix;
  ir::RegFile file;
};
// Longest prefixes first so that "od3" is not read as register file "o".
constexpr NamedReg kIndexed[] = {
    {"od", ir::RegFile::AttrOut}, {"ot", ir::RegFile::TexCrdOut}, {"oc", ir::RegFile::ColorOut},
    {"r", ir::RegFile::Temp},     {"v", ir::RegFile::Input},      {"c", ir::RegFile::Const},
    {"a", ir::RegFile::Addr},     {"t", ir::RegFile::Texture},    {"s", ir::RegFile::Sampler},
    {"i", ir::RegFile::ConstInt}, {"b", ir::RegFile::ConstBool},  {"l", ir::RegFile::Label},
    {"o", ir::RegFile::Output},   {"p", ir::RegFile::Predicate},
};

} // namespace

bool Parser::register_name(const Token& t, std::string_view name, Operand& out, bool& has_index) {
  ir::SourceLoc loc = t.loc;
  if (name.size() <= t.text.size()) loc.length = static_cast<uint32_t>(name.size());
  static constexpr std::pair<std::string_view, std::pair<ir::RegFile, uint32_t>> fixed[] = {
      {"opos", {ir::RegFile::RastOut, ir::kRastPos}},
      {"ofog", {ir::RegFile::RastOut, ir::kRastFog}},
      {"opts", {ir::RegFile::RastOut, ir::kRastPts}},
      {"odepth", {ir::RegFile::DepthOut, 0}},
      {"al", {ir::RegFile::Loop, 0}},
      {"vpos", {ir::RegFile::Misc, ir::kMiscPosition}},
      {"vface", {ir::RegFile::Misc, ir::kMiscFace}}};
  for (auto& [n, reg] : fixed)
    if (name == n) {
      out.file = reg.first;
      out.index = reg.second;
      has_index = true;
      return true;
    }
  for (const NamedReg& r : kIndexed) {
    if (!name.starts_with(r.prefix)) continue;
    std::string_view digits = name.substr(r.prefix.size());
    if (digits.find_first_not_of("0123456789") != std::string_view::npos) break;
    out.file = r.file;
    has_index = !digits.empty();
    if (!has_index) return true; // "c" is only valid before "[...]"; the caller checks
    uint32_t idx = 0;
    auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), idx);
    if (ec != std::errc() || idx > kMaxRegisterIndex)
      return fail(loc, "bad-number", fmt::format("register index '{}' is too large", digits));
    // a0 and p0 are the only address and predicate registers; "a1" would print back as a0.
    if ((r.file == ir::RegFile::Addr || r.file == ir::RegFile::Predicate) && idx != 0) break;
    out.index = idx;
    return true;
  }
  return fail(loc, "unknown-register",
              fmt::format("unknown register '{}'", t.text.substr(0, name.size())));
}

bool Parser::operand(Operand& out) {
  out.loc = cur().loc;
  if (at_punct("-")) {
    out.neg = true;
    advance();
  } else if (at_punct("!")) {
    out.bnot = true;
    advance();
  } else if (cur().kind == TokKind::Number && peek().kind == TokKind::Punct && peek().text == "-") {
    if (cur().text != "1" && cur().text != "1.0")
      return fail(cur().loc, "syntax", "only '1-reg' (complement) may precede a register");
    out.comp = true;
    advance();
    advance();
  }
  const Token& t = cur();
  if (t.kind != TokKind::Ident)
    return fail(t.loc, "syntax", fmt::format("expected a register, found {}", describe(t)));
  advance();
  std::string name = lower(t.text);
  std::string_view regname = name;
  size_t us = name.find('_');
  if (us != std::string::npos) regname = std::string_view(name).substr(0, us);
  bool has_index = false;
  if (!register_name(t, regname, out, has_index)) return false;
  if (us != std::string::npos) {
    out.modifier = name.substr(us + 1);
    out.modifier_loc = t.loc;
    if (t.text.size() == name.size()) {
      out.modifier_loc.col += static_cast<uint32_t>(us);
      out.modifier_loc.length = static_cast<uint32_t>(name.size() - us);
    }
  }
  if (at_punct("[")) {
    if (!relative(out, has_index)) return false;
    // A modifier may follow the brackets: c[a0.x + 1]_bx2.
    if (cur().kind == TokKind::Ident && !cur().space_before && cur().text.starts_with('_') &&
        out.modifier.empty()) {
      out.modifier = lower(cur().text.substr(1));
      out.modifier_loc = cur().loc;
      advance();
    }
  } else if (!has_index) {
    return fail(span_to_prev(out.loc), "unknown-register",
                fmt::format("register '{}' needs an index", t.text));
  }
  if (at_punct(".")) {
    advance();
    const Token& s = cur();
    if (s.kind != TokKind::Ident)
      return fail(s.loc, "syntax",
                  fmt::format("expected a swizzle or write mask, found {}", describe(s)));
    out.suffix = s.text;
    out.suffix_loc = s.loc;
    advance();
  }
  out.loc = span_to_prev(out.loc);
  return true;
}

bool Parser::relative(Operand& out, bool has_index) {
  ir::SourceLoc open = cur().loc;
  advance(); // '['
  int64_t offset = has_index ? out.index : 0;
  bool expect_term = true;
  int sign = 1;
  while (true) {
    const Token& t = cur();
    if (at_eol()) return fail(open, "syntax", "missing ']'");
    if (at_punct("]")) {
      if (expect_term) return fail(t.loc, "syntax", "expected a register or a number before ']'");
      advance();
      break;
    }
    if (!expect_term) {
      if (!at_punct("+") && !at_punct("-"))
        return fail(t.loc, "syntax",
                    fmt::format("expected '+', '-' or ']', found {}", describe(t)));
      sign = t.text == "-" ? -1 : 1;
      expect_term = true;
      advance();
      continue;
    }
    expect_term = false;
    if (t.kind == TokKind::Number) {
      uint32_t v = 0;
      auto [p, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
      if (ec != std::errc() || p != t.text.data() + t.text.size() || v > kMaxRegisterIndex)
        return fail(t.loc, "bad-number", fmt::format("'{}' is not a register offset", t.text));
      offset += sign * static_cast<int64_t>(v);
      advance();
      continue;
    }
    std::string reg = t.kind == TokKind::Ident ? lower(t.text) : std::string();
    if (reg != "a0" && reg != "al")
      return fail(t.loc, reg.empty() ? "syntax" : "unknown-register",
                  fmt::format("expected a0 or aL inside [...], found {}", describe(t)));
    if (out.rel) return fail(t.loc, "syntax", "only one address register inside [...]");
    if (sign < 0) return fail(t.loc, "syntax", "an address register cannot be subtracted");
    ir::RelAddr rel;
    rel.file = reg == "al" ? ir::RegFile::Loop : ir::RegFile::Addr;
    rel.loc = t.loc;
    advance();
    if (rel.file == ir::RegFile::Addr) {
      // Microsoft's assembler writes the swizzle into the vs_2_0 address token as it stands:
      // identity for a bare a0, 0xF4 for a0.xyww (a short one repeats its last letter); the
      // first component selected is the one added (DXVK, wined3d read it the same way).
      int comps[4] = {0, 1, 2, 3};
      if (at_punct(".")) {
        advance();
        const Token& c = cur();
        std::string letters = c.kind == TokKind::Ident ? lower(c.text) : std::string();
        bool ok = !letters.empty() && letters.size() <= 4;
        for (size_t i = 0; ok && i < 4; ++i) {
          comps[i] = component_of(letters[i < letters.size() ? i : letters.size() - 1]);
          ok = comps[i] >= 0;
        }
        if (!ok)
          return fail(c.loc, "syntax",
                      fmt::format("expected components of a0 (.x … .xyzw), found {}", describe(c)));
        advance();
        rel.loc = span_to_prev(t.loc);
      }
      rel.swizzle = ir::make_swizzle(comps[0], comps[1], comps[2], comps[3]);
      rel.component = static_cast<uint8_t>(comps[0]);
    }
    out.rel = rel;
  }
  if (offset < 0 || offset > kMaxRegisterIndex)
    return fail(span_to_prev(out.loc), "bad-number",
                fmt::format("register index {} is out of range", offset));
  out.index = static_cast<uint32_t>(offset);
  return true;
}

bool Parser::to_dst(const Operand& in, ir::DstOperand& out) {
  if (in.neg || in.comp || in.bnot || !in.modifier.empty())
    return fail(in.loc, "syntax", "a destination takes no modifier or negation");
  out.file = in.file;
  out.index = in.index;
  out.loc = in.loc;
  out.rel = in.rel; // o[a0.x + n] in vs_3_0; the validator says where it is allowed
  out.mask = ir::kFullMask;
  if (!in.suffix) return true;
  std::string letters = lower(*in.suffix);
  uint8_t mask = 0;
  int last = -1;
  for (char c : letters) {
    int comp = component_of(c);
    if (comp <= last || letters.size() > 4)
      return fail(
          in.suffix_loc, "syntax",
          fmt::format("bad write mask '.{}' (components in xyzw or rgba order)", *in.suffix));
    last = comp;
    mask = static_cast<uint8_t>(mask | (1 << comp));
  }
  out.mask = mask;
  return true;
}

bool Parser::to_src(const Operand& in, ir::SrcOperand& out) {
  using M = ir::SrcMod;
  out.file = in.file;
  out.index = in.index;
  out.rel = in.rel;
  out.loc = in.loc;
  M mod = in.neg ? M::Neg : in.comp ? M::Comp : in.bnot ? M::Not : M::None;
  if (!in.modifier.empty()) {
    // The suffix spellings come from the modifier table; _db and _da are the rgba names of
    // _dz and _dw.
    const std::string_view name = in.modifier == "db"   ? "dz"
                                  : in.modifier == "da" ? "dw"
                                                        : std::string_view(in.modifier);
    auto spelled = [&](const ir::SrcModInfo& m, bool negated) {
      return m.suffix.size() == name.size() + 1 && m.suffix.substr(1) == name &&
             m.negate == negated;
    };
    auto plain = std::find_if(std::begin(ir::kSrcMods), std::end(ir::kSrcMods),
                              [&](const auto& m) { return spelled(m, false); });
    auto negated = std::find_if(std::begin(ir::kSrcMods), std::end(ir::kSrcMods),
                                [&](const auto& m) { return spelled(m, true); });
    if (plain == std::end(ir::kSrcMods))
      return fail(in.modifier_loc, "unknown-modifier",
                  fmt::format("unknown source modifier '_{}'", in.modifier));
    if (in.comp || in.bnot || (in.neg && negated == std::end(ir::kSrcMods)))
      return fail(in.loc, "syntax",
                  fmt::format("'_{}' cannot be combined with {}", in.modifier,
                              in.comp   ? "'1-'"
                              : in.bnot ? "'!'"
                                        : "negation"));
    mod = in.neg ? negated->mod : plain->mod;
  }
  out.mod = mod;
  out.swizzle = ir::kIdentitySwizzle;
  if (!in.suffix) return true;
  std::string letters = lower(*in.suffix);
  if (letters.empty() || letters.size() > 4)
    return fail(in.suffix_loc, "syntax", fmt::format("bad swizzle '.{}'", *in.suffix));
  int comps[4] = {0, 0, 0, 0};
  for (size_t i = 0; i < 4; ++i) {
    // A short swizzle repeats its last component: .xy = .xyyy.
    char c = letters[i < letters.size() ? i : letters.size() - 1];
    comps[i] = component_of(c);
    if (comps[i] < 0)
      return fail(in.suffix_loc, "syntax", fmt::format("bad swizzle '.{}'", *in.suffix));
  }
  out.swizzle = ir::make_swizzle(comps[0], comps[1], comps[2], comps[3]);
  return true;
}

} // namespace tierlift::assembly::detail
