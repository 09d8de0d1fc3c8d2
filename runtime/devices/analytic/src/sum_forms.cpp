// Pixel listing → output colour as Σ_k weight_k · sample_k: every register component is a
// linear form over the channels of the samples taken so far, plus a constant, or "opaque".
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

#include "linear_forms.h"
#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/semantics.h"

namespace tierlift::analytic::detail {

namespace {

// A sample is identified by the coordinate register it reads and the stage/sampler.
using SampleKey = std::pair<uint32_t, uint32_t>; // (texcoord, sampler)

struct Form {
  std::map<SampleKey, std::array<double, 4>> coef; // per sample, per sample channel
  double k = 0;
  std::string opaque;
  bool is_constant() const {
    if (!opaque.empty()) return false;
    for (const auto& [key, c] : coef)
      if (c != std::array<double, 4>{}) return false;
    return true;
  }
};
using Reg = std::array<Form, 4>;

Form make_opaque(std::string why) {
  Form f;
  f.opaque = std::move(why);
  return f;
}
Form affine(Form f, double scale, double bias) {
  if (!f.opaque.empty()) return f;
  for (auto& [key, c] : f.coef)
    for (double& x : c) x *= scale;
  f.k = f.k * scale + bias;
  return f;
}
Form sum(const Form& a, const Form& b) {
  if (!a.opaque.empty()) return a;
  if (!b.opaque.empty()) return b;
  Form r = a;
  for (const auto& [key, c] : b.coef) {
    auto& dst = r.coef[key];
    for (int i = 0; i < 4; ++i) dst[i] += c[i];
  }
  r.k += b.k;
  return r;
}
Form product(const Form& a, const Form& b, const ir::SourceLoc& loc) {
  if (!a.opaque.empty()) return a;
  if (!b.opaque.empty()) return b;
  if (a.is_constant()) return affine(b, a.k, 0);
  if (b.is_constant()) return affine(a, b.k, 0);
  return make_opaque(where(loc) + ": product of two samples");
}

class Evaluator {
public:
  Evaluator(const ir::Program& p, const std::vector<Vec4>& consts, const ColourConstants& colours)
      : p_(p), defs_(ir::fold_defs(p)), consts_(consts), colours_(colours) {}

  SumForm run() {
    SumForm out;
    for (const ir::Instruction& in : p_.code) {
      out.error = step(in);
      if (!out.error.empty()) return out;
    }
    const bool ps1x = ir::is_ps1x(p_.profile);
    auto it = ps1x ? regs_.find({ir::RegFile::Temp, 0}) : regs_.find({ir::RegFile::ColorOut, 0});
    if (it == regs_.end()) {
      out.error = ps1x ? "r0 (the output) is never written" : "oC0 is never written";
      return out;
    }
    std::map<SampleKey, Tap> taps;
    for (int c = 0; c < 4; ++c) {
      const Form& f = it->second[c];
      if (!f.opaque.empty()) {
        out.error =
            fmt::format("output .{} is not a weighted sum of samples: {}", "rgba"[c], f.opaque);
        return out;
      }
      if (f.k != 0) {
        out.error = fmt::format("output .{} has a constant term {}", "rgba"[c], f.k);
        return out;
      }
      for (const auto& [key, co] : f.coef)
        for (int s = 0; s < 4; ++s) {
          if (s != c && co[s] != 0) {
            out.error = fmt::format("output .{} reads channel .{} of a sample (swizzled)",
                                    "rgba"[c], "rgba"[s]);
            return out;
          }
          if (s == c) {
            Tap& t = taps[key];
            t.texcoord = key.first;
            t.sampler = key.second;
            t.weight[c] = co[c];
          }
        }
    }
    for (const SampleKey& key : order_)
      if (auto t = taps.find(key); t != taps.end()) out.taps.push_back(t->second);
    if (clamped_) out.notes.push_back("ps_1_x constants were clamped to [-1, 1]");
    if (ps1x)
      out.notes.push_back(
          "ps_1_x register clamps to [-1, 1] are not part of the taps: linear_pass clamps "
          "the samples and the final sum, exact while no partial sum leaves the range and "
          "comes back (non-negative weights and samples)");
    return out;
  }

private:
  Form sample_form(uint32_t texcoord, uint32_t sampler, int channel) {
    SampleKey key{texcoord, sampler};
    if (std::find(order_.begin(), order_.end(), key) == order_.end()) order_.push_back(key);
    Form f;
    f.coef[key][channel] = 1.0;
    return f;
  }

  Form read(const ir::SrcOperand& s, int comp) {
    int c = ir::swizzle_component(s.swizzle, comp);
    Form f;
    if (s.rel) return make_opaque(where(s.loc) + ": relative addressing");
    switch (s.file) {
    case ir::RegFile::Const: {
      bool clamp = ir::is_ps1x(p_.profile);
      f.k = constant_value(defs_, consts_, s.index, clamp, &clamped_)[c];
      break;
    }
    case ir::RegFile::Input:
      if (s.index < colours_.size() && colours_[s.index]) {
        f.k = (*colours_[s.index])[c];
        break;
      }
      return make_opaque(fmt::format("{}: reads v{}, a vertex colour that is not one constant "
                                     "over the quad",
                                     where(s.loc), s.index));
    case ir::RegFile::Temp:
    case ir::RegFile::Texture: {
      auto it = regs_.find({s.file, s.index});
      if (it == regs_.end())
        return make_opaque(fmt::format("{}: reads {} before a sample was written to it",
                                       where(s.loc), ir::register_name(s.file, s.index)));
      f = it->second[c];
      break;
    }
    default:
      return make_opaque(fmt::format("{}: reads {}, which is not a sample or a constant",
                                     where(s.loc), ir::register_name(s.file, s.index)));
    }
    auto m = affine_modifier(s.mod);
    if (!m) return make_opaque(where(s.loc) + ": source modifier is not affine");
    return affine(f, m->scale, m->bias);
  }

  std::string step(const ir::Instruction& in) {
    const ir::OpInfo& info = ir::op_info(in.op);
    if (info.cls == ir::OpClass::Flow && in.op != ir::Opcode::Phase)
      return fmt::format("{}: flow control ({}) is outside the linear model", where(in.loc),
                         info.mnemonic);
    if (!in.dst || in.op == ir::Opcode::Nop || in.op == ir::Opcode::Phase) return "";
    if (in.src.size() < info.num_src)
      return fmt::format("{}: {} has too few operands", where(in.loc), info.mnemonic);
    const ir::DstOperand& d = *in.dst;
    ir::Result<std::optional<SampleKey>> key = sample_key(in);
    if (!key) return key.message();
    const std::optional<SampleKey> sampled = *key;
    Reg& r = regs_[{d.file, d.index}];
    Reg next = r;
    const double scale = std::ldexp(1.0, in.mods.shift); // _x2 … _d8
    // The components the opcode really writes (the table's column), not the bare mask.
    const uint8_t written = ir::written_mask(in, p_.profile);
    for (int c = 0; c < 4; ++c) {
      if (!(written & (1u << c))) continue;
      Form v;
      if (sampled) {
        v = sample_form(sampled->first, sampled->second, c);
      } else {
        switch (in.op) {
        case ir::Opcode::Mov: v = read(in.src[0], c); break;
        case ir::Opcode::Add: v = sum(read(in.src[0], c), read(in.src[1], c)); break;
        case ir::Opcode::Sub: v = sum(read(in.src[0], c), affine(read(in.src[1], c), -1, 0)); break;
        case ir::Opcode::Mul: v = product(read(in.src[0], c), read(in.src[1], c), in.loc); break;
        case ir::Opcode::Mad:
          v = sum(product(read(in.src[0], c), read(in.src[1], c), in.loc), read(in.src[2], c));
          break;
        default: v = make_opaque(fmt::format("{}: {} is not linear", where(in.loc), info.mnemonic));
        }
        v = affine(v, scale, 0);
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
  const ColourConstants& colours_;
  bool clamped_ = false;
  std::vector<SampleKey> order_;
  std::map<std::pair<ir::RegFile, uint32_t>, Reg> regs_;
};

} // namespace

// texld / tex: the coordinate register must be an unmodified t# read as .xy.
ir::Result<std::optional<SampleKey>> sample_key(const ir::Instruction& in) {
  const ir::OpInfo& info = ir::op_info(in.op);
  auto fail = [](std::string why) { return ir::fail("ps", "analytic", std::move(why)); };
  if (!in.dst) return std::optional<SampleKey>();
  const ir::DstOperand& d = *in.dst;
  switch (in.op) {
  case ir::Opcode::Tex: return std::optional<SampleKey>(SampleKey{d.index, d.index});
  case ir::Opcode::TexLd:
  case ir::Opcode::TexLd14: {
    if (in.src.empty()) return fail(where(in.loc) + ": texld without a coordinate");
    const ir::SrcOperand& s = in.src[0];
    if (s.file != ir::RegFile::Texture)
      return fail(where(s.loc) + ": dependent read (coordinate is not a t# register)");
    if (s.mod != ir::SrcMod::None || ir::swizzle_component(s.swizzle, 0) != 0 ||
        ir::swizzle_component(s.swizzle, 1) != 1)
      return fail(where(s.loc) + ": coordinate is modified or swizzled");
    return std::optional<SampleKey>(SampleKey{
        s.index, in.op == ir::Opcode::TexLd && in.src.size() > 1 ? in.src[1].index : d.index});
  }
  default:
    if (info.cls == ir::OpClass::Texture)
      return fail(
          fmt::format("{}: {} is not a plain texture sample", where(in.loc), info.mnemonic));
    return std::optional<SampleKey>();
  }
}

SumForm evaluate_sum(const ir::Program& ps, const std::vector<Vec4>& consts,
                     const ColourConstants& colours) {
  return Evaluator(ps, consts, colours).run();
}

} // namespace tierlift::analytic::detail
