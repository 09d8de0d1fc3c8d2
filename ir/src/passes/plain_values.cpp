// Analysis: plain values of a pixel program (plain_values.h).
#include "tierlift/ir/plain_values.h"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/profile.h"
#include "tierlift/ir/registers.h"
#include "tierlift/ir/semantics.h"

namespace tierlift::ir {
namespace {

// One component: known to be +0 or in [lo, hi] (an empty interval, lo > hi: +0 only), with
// FLT_MIN <= lo and hi <= FLT_MAX when the interval is not empty. Every bound is a value the
// fp32 operations themselves produce from the bounds: rounding to nearest is monotonic, so a
// bound computed the devices' way bounds every value they compute.
struct Plain {
  bool known = false;
  float lo = std::numeric_limits<float>::infinity();
  float hi = 0.0f;
  bool zero_only() const { return lo > hi; }
};
using Lanes = std::array<Plain, 4>;

Plain unknown() {
  return {};
}
Plain zero() {
  return {true, std::numeric_limits<float>::infinity(), 0.0f};
}
Plain interval(float lo, float hi) {
  // A product's lower bound keeps a margin above FLT_MIN: a result just below it may round
  // up to FLT_MIN in one mode and flush to 0 in another.
  if (!(lo >= FLT_MIN) || !(hi <= FLT_MAX)) return unknown();
  return {true, lo, hi};
}

// The constant x as a component: +0, or a positive normal number.
Plain of_constant(float x) {
  if (std::bit_cast<uint32_t>(x) == 0) return zero();
  if (x >= FLT_MIN && x <= FLT_MAX) return {true, x, x};
  return unknown();
}

Plain add(const Plain& a, const Plain& b) {
  if (!a.known || !b.known) return unknown();
  if (a.zero_only()) return b; // +0 + x = x, and +0 + +0 = +0 when rounding to nearest
  if (b.zero_only()) return a;
  return interval(std::min(a.lo, b.lo), a.hi + b.hi);
}

Plain mul(const Plain& a, const Plain& b) {
  if (!a.known || !b.known) return unknown();
  if (a.zero_only() || b.zero_only()) return zero();
  const float lo = a.lo * b.lo;
  if (!(lo >= 2 * FLT_MIN)) return unknown();
  return interval(lo, a.hi * b.hi);
}

Plain scale(const Plain& a, float s) {
  if (!a.known || a.zero_only()) return a;
  return interval(a.lo * s, a.hi * s);
}

Plain clamp_above(const Plain& a, float max) {
  if (!a.known || a.zero_only()) return a;
  return {true, std::min(a.lo, max), std::min(a.hi, max)};
}

// The stage an instruction samples through, or -1 when it samples nothing the facts know.
int sampled_stage(const Instruction& ins) {
  switch (ins.op) {
  case Opcode::Tex:
  case Opcode::TexLd14: return ins.dst ? static_cast<int>(ins.dst->index) : -1;
  case Opcode::TexLd:
  case Opcode::TexLdP:
  case Opcode::TexLdB:
  case Opcode::TexLdL: return ins.src.size() >= 2 ? static_cast<int>(ins.src[1].index) : -1;
  default: return -1;
  }
}

class Walk {
public:
  Walk(const Program& p, const PlainValueInputs& in) : p_(p), in_(in), defs_(fold_defs(p)) {}

  PlainValueFacts run() {
    PlainValueFacts out;
    out.sources.assign(p_.code.size(), {0, 0, 0, 0});
    out.within_ps1x_range.assign(p_.code.size(), false);
    std::vector<std::pair<const Instruction*, Lanes>> pending;
    bool flow_seen = false;
    for (size_t i = 0; i < p_.code.size(); ++i) {
      const Instruction& ins = p_.code[i];
      if (!ins.coissue) apply(pending);
      const OpInfo& info = op_info(ins.op);
      if (info.cls == OpClass::Flow) flow_seen = true;
      if (flow_seen) {
        regs_.clear();
        continue;
      }
      std::array<Lanes, 4> read{};
      for (size_t s = 0; s < ins.src.size() && s < 4; ++s) {
        read[s] = source(ins.src[s]);
        for (uint32_t c = 0; c < 4; ++c)
          if (read[s][c].known) out.sources[i][s] |= static_cast<uint8_t>(1u << c);
      }
      if (!ins.dst || ins.op == Opcode::Nop) continue;
      Lanes r = result(ins, read);
      out.within_ps1x_range[i] = store_transform(ins, r);
      pending.emplace_back(&ins, r);
    }
    return out;
  }

private:
  using Key = std::pair<RegFile, uint32_t>;

  Lanes source(const SrcOperand& s) const {
    Lanes v{};
    if (s.file == RegFile::Const) {
      if (s.rel) return v;
      const std::optional<std::array<float, 4>> value =
          constant_value(defs_, s.index, in_.constants);
      if (!value) return v;
      for (uint32_t c = 0; c < 4; ++c) {
        v[c] = of_constant((*value)[c]);
        // ps_1_x reads a constant clamped to [−1, 1].
        if (is_ps1x(p_.profile)) v[c] = clamp_above(v[c], 1.0f);
      }
    } else if (s.rel) {
      return v;
    } else if (auto it = regs_.find({s.file, s.index}); it != regs_.end()) {
      v = it->second;
    }
    if (s.mod != SrcMod::None && s.mod != SrcMod::Abs) return Lanes{}; // |x| = x when plain
    Lanes out{};
    for (uint32_t c = 0; c < 4; ++c) out[c] = v[swizzle_component(s.swizzle, c)];
    return out;
  }

  Lanes result(const Instruction& ins, const std::array<Lanes, 4>& s) const {
    Lanes r{};
    if (const int stage = sampled_stage(ins);
        stage >= 0 && stage < 32 && ((in_.unorm8_stages >> stage) & 1u)) {
      r.fill(interval(1.0f / 255.0f, 1.0f)); // k/255.0f: 0, or 1/255 … 1
      return r;
    }
    for (uint32_t c = 0; c < 4; ++c) {
      switch (ins.op) {
      case Opcode::Mov: r[c] = s[0][c]; break;
      case Opcode::Add: r[c] = add(s[0][c], s[1][c]); break;
      case Opcode::Mul: r[c] = mul(s[0][c], s[1][c]); break;
      case Opcode::Mad: r[c] = add(mul(s[0][c], s[1][c]), s[2][c]); break;
      default: r[c] = unknown();
      }
    }
    return r;
  }

  // The transforms a store applies (shift, ps_1_x range, saturate, fixed point), in the
  // devices' order. Returns whether the range clamp changes nothing.
  bool store_transform(const Instruction& ins, Lanes& r) const {
    const uint8_t mask = written(ins);
    if (ins.mods.shift != 0) {
      const float s = std::ldexp(1.0f, std::clamp<int>(ins.mods.shift, -8, 8));
      for (Plain& x : r) x = scale(x, s);
    }
    const bool ranged = is_ps1x(p_.profile) &&
                        (ins.dst->file == RegFile::Temp || ins.dst->file == RegFile::Texture);
    bool within = ranged && mask != 0;
    for (uint32_t c = 0; c < 4; ++c)
      if ((mask >> c) & 1u)
        within = within && r[c].known && (r[c].zero_only() || r[c].hi <= in_.ps1x_max);
    for (Plain& x : r) {
      if (ranged) x = clamp_above(x, in_.ps1x_max);
      if (ins.mods.sat) x = clamp_above(x, 1.0f);
      if (ranged && in_.ps1x_fixed_bits > 0) x = unknown();
    }
    return within;
  }

  // The components the devices store (the code generator's PendingStore mask): not
  // ir::written_mask, which gives the components left *defined* (texcrd's .w, say, is
  // written but undefined) and ignores a texture instruction's mask; a fact must follow every
  // component that changes.
  uint8_t written(const Instruction& ins) const {
    const uint8_t mask = ins.dst->mask & 0xF;
    return op_info(ins.op).cls == OpClass::Texture
               ? mask
               : static_cast<uint8_t>(mask & op_writes(ins.op, p_.profile));
  }

  void apply(std::vector<std::pair<const Instruction*, Lanes>>& pending) {
    for (const auto& [ins, r] : pending) {
      Lanes& reg = regs_[{ins->dst->file, ins->dst->index}];
      const uint8_t mask = written(*ins);
      for (uint32_t c = 0; c < 4; ++c)
        if ((mask >> c) & 1u) reg[c] = r[c];
    }
    pending.clear();
  }

  const Program& p_;
  const PlainValueInputs& in_;
  const FoldedDefs defs_;
  std::map<Key, Lanes> regs_; // a register not here holds nothing known
};

} // namespace

PlainValueFacts plain_values(const Program& program, const PlainValueInputs& in) {
  return Walk(program, in).run();
}

} // namespace tierlift::ir
