// Building IR by hand for the bytecode tests, so the expected tokens can be derived from
// the format alone, independent of the text parser.
#pragma once

#include <bit>
#include <initializer_list>
#include <vector>

#include "tierlift/ir/program.h"

namespace tierlift::test {

using namespace tierlift::ir;

inline DstOperand D(RegFile f, uint32_t index, uint8_t mask = kFullMask) {
  DstOperand d;
  d.file = f;
  d.index = index;
  d.mask = mask;
  return d;
}

inline SrcOperand S(RegFile f, uint32_t index, uint8_t swizzle = kIdentitySwizzle,
                    SrcMod mod = SrcMod::None) {
  SrcOperand s;
  s.file = f;
  s.index = index;
  s.swizzle = swizzle;
  s.mod = mod;
  return s;
}

inline SrcOperand Rel(SrcOperand s, RegFile by, uint8_t component) {
  s.rel = RelAddr{by, component, {}, std::nullopt};
  return s;
}

// Appends statements with seq numbers in call order, as a parser would.
struct Builder {
  Program p;
  uint32_t seq = 0;
  explicit Builder(Profile profile) { p.profile = profile; }

  Builder& ins(Opcode op, std::optional<DstOperand> dst, std::initializer_list<SrcOperand> src,
               InstrMods mods = {}, bool coissue = false) {
    Instruction i;
    i.op = op;
    i.dst = dst;
    i.src = src;
    i.mods = mods;
    i.coissue = coissue;
    return numbered(p.code, i);
  }
  // Every statement is numbered in call order, as the parser numbers them.
  template <class Statement> Builder& numbered(std::vector<Statement>& to, Statement s) {
    s.seq = seq++;
    to.push_back(s);
    return *this;
  }
  Builder& dcl_input(uint32_t v, DeclUsage usage, uint8_t usage_index = 0,
                     uint8_t mask = kFullMask) {
    Declaration d;
    d.reg = D(RegFile::Input, v, mask);
    d.usage = usage;
    d.usage_index = usage_index;
    return numbered(p.decls, d);
  }
  Builder& dcl_ps(RegFile f, uint32_t index, uint8_t mask = kFullMask, InstrMods mods = {}) {
    Declaration d;
    d.reg = D(f, index, mask);
    d.mods = mods;
    return numbered(p.decls, d);
  }
  Builder& dcl_sampler(uint32_t s, SamplerType type) {
    Declaration d;
    d.reg = D(RegFile::Sampler, s);
    d.sampler_type = type;
    return numbered(p.decls, d);
  }
  Builder& def(RegFile f, uint32_t index, std::array<uint32_t, 4> raw) {
    ConstDef c;
    c.file = f;
    c.index = index;
    c.raw = raw;
    return numbered(p.defs, c);
  }
  Builder& deff(uint32_t index, float a, float b, float c, float d) {
    return def(RegFile::Const, index,
               {std::bit_cast<uint32_t>(a), std::bit_cast<uint32_t>(b), std::bit_cast<uint32_t>(c),
                std::bit_cast<uint32_t>(d)});
  }
};

inline InstrMods Mods(bool sat, int shift = 0, bool pp = false, bool centroid = false) {
  InstrMods m;
  m.sat = sat;
  m.shift = static_cast<int8_t>(shift);
  m.pp = pp;
  m.centroid = centroid;
  return m;
}

} // namespace tierlift::test
