// Vertex listing → oT# as affine forms of the texcoord input: every register component is
// Σ_c a_c · texcoord.c + k, or "opaque" (depends on something else, or is not affine).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

#include "linear_forms.h"
#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/semantics.h"
#include "tierlift/pass/pass.h"

namespace tierlift::analytic::detail {

namespace {

// The texcoord input (u, v, 0, 1) at the quad's corners: top-left, top-right, bottom-left,
// bottom-right (the vertex data every full-screen pass is drawn with).
constexpr float kQuadCornerUv[4][4] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, {1, 1, 0, 1}};

struct Affine {
  std::array<double, 4> tc{}; // coefficients on texcoord.x, .y, .z, .w
  double k = 0;
  // The component's value at the quad's four corners, computed as the devices' vertex stage
  // computes it: each instruction in fp32, one rounding per operation (NUMERICS.md rules 8,
  // 14: a product with a zero factor is +0, mad is not fused).
  std::array<float, 4> at{};
  std::string opaque; // non-empty: not affine in the texcoord; says why
  bool is_constant() const { return opaque.empty() && tc == std::array<double, 4>{}; }
};
using Reg = std::array<Affine, 4>;

Affine make_opaque(std::string why) {
  Affine a;
  a.opaque = std::move(why);
  return a;
}

// Negation (the only scaling a source modifier of vs_1_1/vs_2_0 applies): exact in fp32.
Affine negated(Affine a) {
  for (double& c : a.tc) c = -c;
  a.k = -a.k;
  for (float& v : a.at) v = -v;
  return a;
}

Affine sum(const Affine& a, const Affine& b) {
  if (!a.opaque.empty()) return a;
  if (!b.opaque.empty()) return b;
  Affine r;
  for (int c = 0; c < 4; ++c) r.tc[c] = a.tc[c] + b.tc[c];
  r.k = a.k + b.k;
  for (int q = 0; q < 4; ++q) r.at[q] = a.at[q] + b.at[q];
  return r;
}

// fp32 product with D3D9's zero rule, written from its definition (NUMERICS.md rule 8).
float legacy_product(float x, float y) {
  return (x == 0.0f || y == 0.0f) ? 0.0f : x * y;
}

Affine product(const Affine& a, const Affine& b, const ir::SourceLoc& loc) {
  if (!a.opaque.empty()) return a;
  if (!b.opaque.empty()) return b;
  Affine r;
  if (a.is_constant() || b.is_constant()) {
    const Affine& konst = a.is_constant() ? a : b;
    const Affine& other = a.is_constant() ? b : a;
    for (int c = 0; c < 4; ++c) r.tc[c] = other.tc[c] * konst.k;
    r.k = other.k * konst.k;
  } else {
    return make_opaque(where(loc) + ": product of two texcoord terms");
  }
  for (int q = 0; q < 4; ++q) r.at[q] = legacy_product(a.at[q], b.at[q]);
  return r;
}

class Evaluator {
public:
  Evaluator(const ir::Program& p, const std::vector<Vec4>& consts)
      : p_(p), defs_(ir::fold_defs(p)), consts_(consts) {}

  CoordForms run() {
    CoordForms out;
    // Every texcoord input carries the quad's uv (pass::texcoord_inputs, the rule the
    // devices feed the quad by); the first one is reported.
    tc_inputs_ = pass::texcoord_inputs(p_);
    if (tc_inputs_.empty()) {
      out.error = "no dcl_texcoord input";
      return out;
    }
    out.texcoord_input = tc_inputs_.front();
    for (const ir::Instruction& in : p_.code) {
      std::string err = step(in);
      if (!err.empty()) {
        out.error = err;
        return out;
      }
    }
    for (uint32_t n = 0; n < out.colour.size(); ++n) out.colour[n] = colour_constant(n);
    for (uint32_t n = 0; n < 8; ++n) {
      auto it = regs_.find({ir::RegFile::TexCrdOut, n});
      if (it == regs_.end()) {
        out.why_not[n] = fmt::format("oT{} is never written", n);
        continue;
      }
      const Reg& r = it->second;
      std::string why;
      CoordAffine form;
      for (int c = 0; c < 2 && why.empty(); ++c) {
        const Affine& a = r[c];
        if (!a.opaque.empty()) {
          why = a.opaque;
          break;
        }
        // u' = scale·u + offset: no cross term (u' from v, or from the texcoord's z/w).
        for (int s = 0; s < 4; ++s)
          if (s != c && a.tc[s] != 0.0)
            why = fmt::format("oT{}.{} is not texcoord.{} · scale + constant (it reads "
                              "texcoord.{})",
                              n, "xy"[c], "xy"[c], "xyzw"[s]);
        if (why.empty() && !(std::isfinite(a.tc[c]) && std::isfinite(a.k)))
          why = fmt::format("oT{}.{}: scale or offset is not finite", n, "xy"[c]);
        form.scale[c] = a.tc[c];
        form.offset[c] = a.k;
        for (int q = 0; q < 4; ++q) form.corner[q][c] = a.at[q];
      }
      if (why.empty())
        out.coord[n] = form;
      else
        out.why_not[n] = why;
    }
    return out;
  }

private:
  // oD# when every component is the same fp32 value at the quad's four corners (what the
  // devices then interpolate), saturated as the pixel stage reads it; nullopt otherwise.
  std::optional<std::array<double, 4>> colour_constant(uint32_t n) const {
    auto it = regs_.find({ir::RegFile::AttrOut, n});
    if (it == regs_.end()) return std::nullopt;
    std::array<double, 4> v{};
    for (int c = 0; c < 4; ++c) {
      const Affine& a = it->second[c];
      if (!a.is_constant()) return std::nullopt;
      for (int q = 1; q < 4; ++q)
        if (a.at[q] != a.at[0]) return std::nullopt;
      v[c] = std::clamp(double(a.at[0]), 0.0, 1.0);
    }
    return v;
  }

  Affine read(const ir::SrcOperand& s, int comp) {
    int c = ir::swizzle_component(s.swizzle, comp);
    Affine a;
    if (s.rel) return make_opaque(where(s.loc) + ": relative addressing");
    switch (s.file) {
    case ir::RegFile::Input:
      if (std::find(tc_inputs_.begin(), tc_inputs_.end(), s.index) == tc_inputs_.end())
        return make_opaque(
            fmt::format("{}: reads v{}, not the texcoord input", where(s.loc), s.index));
      a.tc[c] = 1.0;
      for (int q = 0; q < 4; ++q) a.at[q] = kQuadCornerUv[q][c];
      break;
    case ir::RegFile::Const:
      a.k = constant_value(defs_, consts_, s.index, false, nullptr)[c];
      a.at.fill(static_cast<float>(a.k)); // API constants are floats: exact
      break;
    case ir::RegFile::Temp: {
      auto it = regs_.find({s.file, s.index});
      if (it == regs_.end()) return make_opaque(where(s.loc) + ": reads an unwritten register");
      a = it->second[c];
      break;
    }
    default: return make_opaque(where(s.loc) + ": reads a register that is not v#, c# or r#");
    }
    if (s.mod == ir::SrcMod::None) return a;
    if (s.mod == ir::SrcMod::Neg) return negated(a);
    return make_opaque(where(s.loc) + ": source modifier");
  }

  std::string step(const ir::Instruction& in) {
    const ir::OpInfo& info = ir::op_info(in.op);
    if (info.cls == ir::OpClass::Flow && in.op != ir::Opcode::Label)
      return fmt::format("{}: flow control ({}) is outside the linear model", where(in.loc),
                         info.mnemonic);
    if (!in.dst || in.op == ir::Opcode::Nop) return "";
    if (in.src.size() < info.num_src)
      return fmt::format("{}: {} has too few operands", where(in.loc), info.mnemonic);
    const ir::DstOperand& d = *in.dst;
    Reg& r = regs_[{d.file, d.index}];
    Reg next = r;
    // The components the opcode really writes (the table's column), not the bare mask.
    const uint8_t written = ir::written_mask(in, p_.profile);
    for (int c = 0; c < 4; ++c) {
      if (!(written & (1u << c))) continue;
      Affine v;
      switch (in.op) {
      case ir::Opcode::Mov: v = read(in.src[0], c); break;
      case ir::Opcode::Add: v = sum(read(in.src[0], c), read(in.src[1], c)); break;
      case ir::Opcode::Sub: v = sum(read(in.src[0], c), negated(read(in.src[1], c))); break;
      case ir::Opcode::Mul: v = product(read(in.src[0], c), read(in.src[1], c), in.loc); break;
      case ir::Opcode::Mad:
        v = sum(product(read(in.src[0], c), read(in.src[1], c), in.loc), read(in.src[2], c));
        break;
      default: v = make_opaque(fmt::format("{}: {} is not linear", where(in.loc), info.mnemonic));
      }
      if (in.mods.sat) v = make_opaque(where(in.loc) + ": _sat");
      next[c] = v;
    }
    r = next;
    return "";
  }

  const ir::Program& p_;
  const ir::FoldedDefs defs_; // the listing's defs, folded once
  const std::vector<Vec4>& consts_;
  std::vector<uint32_t> tc_inputs_;
  std::map<std::pair<ir::RegFile, uint32_t>, Reg> regs_;
};

} // namespace

CoordForms evaluate_coords(const ir::Program& vs, const std::vector<Vec4>& consts) {
  return Evaluator(vs, consts).run();
}

} // namespace tierlift::analytic::detail
