// The prelude (declarations, special constants), the tail (closing blocks, output writes,
// subroutines) and the validator as the judge of each proposed instruction.
#include "builder.h"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <limits>
#include <set>

#include "tierlift/assembly/validator.h"
#include "tierlift/ir/profile.h"
#include "tierlift/ir/semantics.h"

namespace tierlift::gen::detail {

using ir::Opcode;
using ir::RegFile;

ir::SrcOperand src_reg(RegFile f, uint32_t index, uint8_t swizzle, ir::SrcMod mod) {
  ir::SrcOperand s;
  s.file = f;
  s.index = index;
  s.swizzle = swizzle;
  s.mod = mod;
  return s;
}

ir::DstOperand dst_reg(RegFile f, uint32_t index, uint8_t mask) {
  ir::DstOperand d;
  d.file = f;
  d.index = index;
  d.mask = mask;
  return d;
}

ir::Instruction make(Opcode op, std::optional<ir::DstOperand> dst,
                     std::vector<ir::SrcOperand> src) {
  ir::Instruction ins;
  ins.op = op;
  ins.dst = dst;
  ins.src = std::move(src);
  return ins;
}

namespace {

uint32_t bits(float f) {
  return std::bit_cast<uint32_t>(f);
}

ir::ConstDef def(RegFile f, uint32_t index, std::array<uint32_t, 4> raw) {
  ir::ConstDef d;
  d.file = f;
  d.index = index;
  d.raw = raw;
  return d;
}

ir::ConstDef def_f(uint32_t index, float x, float y, float z, float w) {
  return def(RegFile::Const, index, {bits(x), bits(y), bits(z), bits(w)});
}

ir::Declaration decl(RegFile f, uint32_t index, ir::DeclUsage usage = ir::DeclUsage::Position,
                     uint8_t usage_index = 0) {
  ir::Declaration d;
  d.reg = dst_reg(f, index);
  d.usage = usage;
  d.usage_index = usage_index;
  return d;
}

} // namespace

Builder::Builder(ir::Profile p, const GenerateOptions& o, std::uint64_t seed)
    : profile(p), options(o), rng(seed),
      temps(std::min<uint32_t>(ir::limits(p).temps, generated_temps(p))) {
  base_.profile = p;
  if (!ir::is_vertex(p) && ir::is_sm2_or_later(p) && o.extra_outputs) {
    want_more_colours = rng.chance(0.2);
    want_depth = rng.chance(0.1);
  }
  prelude();
}

// Every input the body may read is declared here; finish() drops the unread ones. The
// defined constants carry the special values of NUMERICS.md the differential run must see
// (0, -0, ±1, large, the smallest normal, a denormal; ±inf and NaN where the profile has no
// [-1, 1] range clamp: the parser reads "inf", "nan" and raw bits, so def can say them).
void Builder::prelude() {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto random_def = [&](uint32_t index, float scale) {
    return def_f(index, (rng.unit() * 2 - 1) * scale, (rng.unit() * 2 - 1) * scale,
                 (rng.unit() * 2 - 1) * scale, (rng.unit() * 2 - 1) * scale);
  };
  if (ir::is_ps1x(profile)) {
    base_.defs = {def_f(0, 0.0f, -0.0f, 1.0f, -1.0f), def_f(1, 0.5f, -0.5f, 1e-40f, -FLT_MIN),
                  random_def(2, 1.0f)};
    // ps_1_1..1_3 need no declarations; ps_1_4 none either.
    return;
  }
  base_.defs = {def_f(0, 0.0f, -0.0f, 1.0f, -1.0f), def_f(1, 1e30f, -1e30f, 1e-40f, -FLT_MIN),
                def_f(2, inf, -inf, nan, 0.5f), random_def(3, 4.0f)};
  if (profile != ir::Profile::vs_1_1) {
    // sincos's constants, as the ISA gives them.
    base_.defs.push_back(
        def_f(kSinCosConst, -1.5500992e-006f, -2.1701389e-005f, 0.0026041667f, 0.00026041668f));
    base_.defs.push_back(def_f(kSinCosConst + 1, -0.020833334f, -0.125f, 1.0f, 0.5f));
  }
  if (profile != ir::Profile::vs_1_1 && profile != ir::Profile::ps_2_0) {
    // rep / loop counters and the bool of if b# / callnz (vs_2_0 and the 2.x, 3.0 profiles).
    base_.defs.push_back(def(RegFile::ConstInt, kRepCounter, {3, 0, 0, 0}));
    base_.defs.push_back(def(RegFile::ConstInt, kLoopCounter, {2, 1, 2, 0}));
    base_.defs.push_back(def(RegFile::ConstBool, 0, {1, 0, 0, 0}));
  }
  if (ir::is_vertex(profile)) {
    base_.decls = {decl(RegFile::Input, 0, ir::DeclUsage::Position),
                   decl(RegFile::Input, 1, ir::DeclUsage::Normal),
                   decl(RegFile::Input, 2, ir::DeclUsage::Color),
                   decl(RegFile::Input, 3, ir::DeclUsage::TexCoord)};
    if (profile == ir::Profile::vs_3_0) vertex30_declarations();
    return;
  }
  if (profile == ir::Profile::ps_3_0) {
    pixel30_inputs();
  } else {
    for (uint32_t t = 0; t < 4; ++t) base_.decls.push_back(decl(RegFile::Texture, t));
    for (uint32_t v = 0; v < 2; ++v) base_.decls.push_back(decl(RegFile::Input, v));
  }
  const ir::SamplerType kinds[] = {ir::SamplerType::Tex2D, ir::SamplerType::Tex2D,
                                   ir::SamplerType::Cube, ir::SamplerType::Volume};
  for (uint32_t s = 0; s < 4; ++s) {
    ir::Declaration d = decl(RegFile::Sampler, s);
    d.sampler_type = options.only_2d_samplers ? ir::SamplerType::Tex2D : kinds[s];
    base_.decls.push_back(d);
  }
}

// vs_3_0: every output is an o# declared with a semantic (o0 the position, the others the
// colours and coordinates the pixel stage reads); s0..s3 are 2D for texldl (vertex texture
// fetch). finish() keeps the outputs written and the samplers read.
void Builder::vertex30_declarations() {
  for (uint32_t o = 0; o < kVertex30Outputs.size(); ++o)
    base_.decls.push_back(
        decl(RegFile::Output, o, kVertex30Outputs[o].first, kVertex30Outputs[o].second));
  for (uint32_t s = 0; s < 4; ++s) {
    ir::Declaration d = decl(RegFile::Sampler, s);
    d.sampler_type = ir::SamplerType::Tex2D;
    base_.decls.push_back(d);
  }
}

// ps_3_0: v0..v3 carry four distinct semantics drawn from the ones the differential run binds
// (color0-1, texcoord0-7: ir/sm3_interface.h), so that the renaming by semantic is exercised
// in every order; vPos (.xy) and vFace are declared too.
void Builder::pixel30_inputs() {
  std::vector<std::pair<ir::DeclUsage, uint8_t>> pool;
  for (uint8_t i = 0; i < 2; ++i) pool.push_back({ir::DeclUsage::Color, i});
  for (uint8_t i = 0; i < 8; ++i) pool.push_back({ir::DeclUsage::TexCoord, i});
  for (uint32_t v = 0; v < kPixel30Inputs; ++v) {
    const std::size_t k = rng.below(pool.size());
    base_.decls.push_back(decl(RegFile::Input, v, pool[k].first, pool[k].second));
    pool.erase(pool.begin() + static_cast<std::ptrdiff_t>(k));
  }
  ir::Declaration pos = decl(RegFile::Misc, ir::kMiscPosition);
  pos.reg.mask = 0x3;
  base_.decls.push_back(pos);
  base_.decls.push_back(decl(RegFile::Misc, ir::kMiscFace));
}

uint8_t Builder::written(RegFile f, uint32_t index, bool this_phase) const {
  uint8_t m = 0;
  for (const ir::Instruction& ins : body_) {
    if (this_phase && ins.op == Opcode::Phase) m = 0;
    if (ins.dst && ins.dst->file == f && ins.dst->index == index)
      m |= ir::written_mask(ins, profile);
  }
  return m;
}

uint8_t Builder::readable(RegFile f, uint32_t index) const {
  switch (f) {
  case RegFile::Temp: return written(f, index);
  case RegFile::Texture:
    if (ir::is_ps11_13(profile)) return written(f, index);
    return profile == ir::Profile::ps_2_0 || profile == ir::Profile::ps_2_x ? ir::kFullMask : 0;
  case RegFile::Input:
  case RegFile::Const: return ir::kFullMask;
  case RegFile::Predicate: return written(f, index);
  // ps_3_0: vPos is declared .xy; vFace is one value (its sign tells the facing).
  case RegFile::Misc:
    if (profile != ir::Profile::ps_3_0) return 0;
    return index == ir::kMiscPosition ? 0x3 : 0x1;
  default: return 0;
  }
}

// The most recently written register among the temps whose four components are written
// (after the last phase marker in ps_1_4), or nullopt.
static std::optional<uint32_t> last_full_temp(const std::vector<ir::Instruction>& code,
                                              ir::Profile p, uint32_t temps) {
  std::array<uint8_t, 16> mask{};
  std::optional<uint32_t> last;
  for (const ir::Instruction& ins : code) {
    if (ins.op == Opcode::Phase) mask.fill(0), last.reset();
    if (ins.op == Opcode::Label) break; // subroutines are not the main program
    if (!ins.dst || ins.dst->file != RegFile::Temp || ins.dst->index >= temps) continue;
    mask[ins.dst->index] |= ir::written_mask(ins, p);
    if (mask[ins.dst->index] == ir::kFullMask) last = ins.dst->index;
  }
  return last;
}

static bool writes(const std::vector<ir::Instruction>& code, RegFile f, uint32_t index) {
  return std::any_of(code.begin(), code.end(), [&](const ir::Instruction& i) {
    return i.dst && i.dst->file == f && i.dst->index == index;
  });
}

// What closes the program: open blocks, the outputs the profile requires (and one that
// shows the body's last result), then the subroutines the body called.
Opcode closer(Opcode opener) {
  switch (opener) {
  case Opcode::Rep: return Opcode::EndRep;
  case Opcode::Loop: return Opcode::EndLoop;
  default: return Opcode::EndIf; // if b#, if p0, if_gt ... if_le
  }
}

std::vector<ir::Instruction> Builder::tail(const std::vector<ir::Instruction>& code) const {
  std::vector<ir::Instruction> t;
  for (auto it = open.rbegin(); it != open.rend(); ++it)
    t.push_back(make(closer(*it), std::nullopt));
  std::vector<ir::Instruction> all = code;
  if (pending_phase) {
    t.push_back(make(Opcode::Phase, std::nullopt));
    all.push_back(t.back());
  }
  const std::optional<uint32_t> full = last_full_temp(all, profile, temps);
  if (profile == ir::Profile::vs_3_0) {
    // o0 is dcl_position, o1 dcl_color0 (kVertex30Outputs).
    t.push_back(make(Opcode::Mov, dst_reg(RegFile::Output, 0), {src_reg(RegFile::Input, 0)}));
    if (full && !writes(code, RegFile::Output, 1))
      t.push_back(make(Opcode::Mov, dst_reg(RegFile::Output, 1), {src_reg(RegFile::Temp, *full)}));
  } else if (ir::is_vertex(profile)) {
    t.push_back(
        make(Opcode::Mov, dst_reg(RegFile::RastOut, ir::kRastPos), {src_reg(RegFile::Input, 0)}));
    if (full && !writes(code, RegFile::AttrOut, 0))
      t.push_back(make(Opcode::Mov, dst_reg(RegFile::AttrOut, 0), {src_reg(RegFile::Temp, *full)}));
  } else if (ir::is_sm2_or_later(profile)) {
    // ps_2_0 / ps_2_x write each oC# once; ps_3_0 may write oC0 earlier, the tail's write
    // is the last one either way.
    const ir::SrcOperand colour = full ? src_reg(RegFile::Temp, *full) : src_reg(RegFile::Input, 0);
    t.push_back(make(Opcode::Mov, dst_reg(RegFile::ColorOut, 0), {colour}));
    if (want_more_colours)
      t.push_back(make(Opcode::Mov, dst_reg(RegFile::ColorOut, 1), {src_reg(RegFile::Input, 1)}));
    if (want_depth)
      t.push_back(make(Opcode::Mov, dst_reg(RegFile::DepthOut, 0),
                       {src_reg(RegFile::Const, 0, ir::replicate_swizzle(2))}));
  } else if (!full || *full != 0) {
    // ps_1_x: r0 is the colour; show the last full result in it.
    t.push_back(make(Opcode::Mov, dst_reg(RegFile::Temp, 0),
                     {full ? src_reg(RegFile::Temp, *full) : src_reg(RegFile::Const, 0)}));
  }
  if (!labels.empty()) {
    t.push_back(make(Opcode::Ret, std::nullopt));
    for (uint32_t l : labels) {
      t.push_back(make(Opcode::Label, std::nullopt, {src_reg(RegFile::Label, l)}));
      t.push_back(make(Opcode::Add, dst_reg(RegFile::Temp, temps - 1),
                       {src_reg(RegFile::Input, 1), src_reg(RegFile::Const, 3)}));
      t.push_back(make(Opcode::Ret, std::nullopt));
    }
  }
  return t;
}

ir::Program Builder::assemble(const std::vector<ir::Instruction>& extra) const {
  ir::Program p = base_;
  p.code = body_;
  p.code.insert(p.code.end(), extra.begin(), extra.end());
  std::vector<ir::Instruction> t = tail(p.code);
  p.code.insert(p.code.end(), t.begin(), t.end());
  uint32_t seq = 0;
  for (auto& d : p.decls) d.seq = seq++;
  for (auto& d : p.defs) d.seq = seq++;
  for (auto& i : p.code) i.seq = seq++;
  return p;
}

bool Builder::accept(const std::vector<ir::Instruction>& ins) {
  if (ins.empty()) return false;
  ir::Program p = assemble(ins);
  ir::DiagnosticSink diags;
  // The 2.x and 3.0 profiles also refuse an instruction that draws a warning (a texld
  // whose level of detail is undefined inside divergent flow, ...); "unused-input" aside,
  // which finish() settles by dropping the declaration. The older profiles' rules have no
  // warning a proposal can cause that the tail does not settle.
  assembly::ValidateOptions options;
  options.warnings = ir::is_sm2x(profile) || ir::is_sm3(profile);
  if (!assembly::validate(p, profile, diags, options)) return false;
  for (const ir::Diagnostic& d : diags.all())
    if (d.severity == ir::Severity::Warning && d.rule != "unused-input") return false;
  body_.insert(body_.end(), ins.begin(), ins.end());
  return true;
}

ir::Program Builder::finish() const {
  ir::Program p = assemble({});
  std::set<std::pair<RegFile, uint32_t>> read;
  for (const ir::Instruction& ins : p.code) {
    for (const ir::SrcOperand& s : ins.src) read.insert({s.file, s.index});
    // vs_3_0 outputs: kept when written (an o[aL + n] write keeps them all).
    if (ins.dst && ins.dst->file == RegFile::Output) {
      for (uint32_t o = 0; o < kVertex30Outputs.size(); ++o)
        if (ins.dst->rel || ins.dst->index == o) read.insert({RegFile::Output, o});
    }
    if (ins.op == Opcode::TexKill && ins.dst) read.insert({ins.dst->file, ins.dst->index});
  }
  std::erase_if(p.decls, [&](const ir::Declaration& d) {
    return !read.count({d.reg.file, d.reg.index});
  });
  return p;
}

} // namespace tierlift::gen::detail
