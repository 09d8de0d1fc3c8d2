// The shapes a profile imposes on a program: vs_2_0's blocks and subroutines, ps_1_1..1_3's
// texture stages before the arithmetic (texture-matrix products on consecutive stages),
// ps_1_4's phases, ps_1_x's co-issued pairs. The rows come from the opcode table.
#include <algorithm>

#include "builder.h"
#include "tierlift/ir/semantics.h"

namespace tierlift::gen::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

std::vector<const ir::OpInfo*> legal_rows(ir::Profile p, ir::OpClass cls) {
  std::vector<const ir::OpInfo*> rows;
  for (const ir::OpInfo& r : ir::opcode_table())
    if (r.cls == cls && ir::legal_in(r, p)) rows.push_back(&r);
  return rows;
}

bool is_if(Opcode op) {
  return op == Opcode::If || (op >= Opcode::IfGt && op <= Opcode::IfLe);
}

bool is_opener(Opcode op) {
  return is_if(op) || op == Opcode::Rep || op == Opcode::Loop || op == Opcode::Call ||
         op == Opcode::CallNz;
}

bool in_loop_or_rep(const Builder& b) {
  return std::any_of(b.open.begin(), b.open.end(),
                     [](Opcode op) { return op == Opcode::Loop || op == Opcode::Rep; });
}

// break, break_comp, breakp: legal only inside a loop or rep (the validator's call).
bool is_break(Opcode op) {
  return op == Opcode::Break || op == Opcode::BreakP ||
         (op >= Opcode::BreakGt && op <= Opcode::BreakLe);
}

// Closes the innermost block, or gives an open if its else. Reverted when refused.
void close_block(Builder& b) {
  const Opcode top = b.open.back();
  if (is_if(top) && !b.has_else.back() && b.rng.chance(0.4)) {
    b.has_else.back() = true;
    if (!b.accept({make(Opcode::Else, std::nullopt)})) b.has_else.back() = false;
    return;
  }
  const bool had_else = b.has_else.back();
  b.open.pop_back();
  b.has_else.pop_back();
  if (!b.accept({make(closer(top), std::nullopt)})) {
    b.open.push_back(top);
    b.has_else.push_back(had_else);
  }
}

// An if/rep/loop opener or a call; the tail closes blocks and appends the subroutines.
bool try_flow(Builder& b, const ir::OpInfo& row) {
  std::vector<ir::Instruction> ins = propose(b, row);
  if (ins.empty()) return false;
  const bool call = row.op == Opcode::Call || row.op == Opcode::CallNz;
  if (call)
    b.labels.push_back(static_cast<uint32_t>(b.labels.size()));
  else
    b.open.push_back(row.op), b.has_else.push_back(false);
  if (b.accept(ins)) return true;
  if (call)
    b.labels.pop_back();
  else
    b.open.pop_back(), b.has_else.pop_back();
  return false;
}

// ps_1_x: an instruction on .rgb co-issued with one on .a.
std::vector<ir::Instruction> coissued_pair(Builder& b, const ir::OpInfo& first,
                                           const ir::OpInfo& second) {
  std::vector<ir::Instruction> a = propose(b, first), c = propose(b, second);
  if (a.size() != 1 || c.size() != 1 || !a[0].dst || !c[0].dst) return {};
  a[0].dst->mask = 0x7;
  c[0].dst->mask = 0x8;
  c[0].coissue = true;
  return {a[0], c[0]};
}

} // namespace

void instruction_loop(Builder& b, std::size_t count, bool texture_rows, bool arith_rows) {
  std::vector<const ir::OpInfo*> rows, arith = legal_rows(b.profile, ir::OpClass::Arith);
  if (arith_rows) rows = arith;
  if (texture_rows) {
    auto t = legal_rows(b.profile, ir::OpClass::Texture);
    rows.insert(rows.end(), t.begin(), t.end());
  }
  std::vector<const ir::OpInfo*> breaks;
  for (const ir::OpInfo* r : legal_rows(b.profile, ir::OpClass::Flow)) {
    if (arith_rows && is_opener(r->op)) rows.push_back(r);
    if (arith_rows && is_break(r->op)) breaks.push_back(r);
  }
  if (rows.empty()) return;
  for (std::size_t i = 0; i < count; ++i) {
    if (!b.open.empty() && b.rng.chance(0.3)) {
      close_block(b);
      continue;
    }
    // Inside a loop or rep, a break of some kind now and then (2.x, 3.0: break, break_comp,
    // breakp); elsewhere the validator would refuse one.
    const bool take_break = !breaks.empty() && in_loop_or_rep(b) && b.rng.chance(0.15);
    const ir::OpInfo* pick = take_break ? b.rng.pick(breaks) : b.rng.pick(rows);
    // breakp needs p0 written inside the loop: favoured once it is, or it seldom appears.
    if (take_break && b.readable(RegFile::Predicate, 0) && b.rng.chance(0.35))
      pick = &ir::op_info(Opcode::BreakP);
    const ir::OpInfo& row = *pick;
    // A row the profile rarely accepts gets a few tries, so that coverage reaches it.
    for (int attempt = 0; attempt < 8; ++attempt) {
      if (row.cls == ir::OpClass::Flow && is_break(row.op)) {
        if (b.accept(propose(b, row))) break;
        continue;
      }
      if (row.cls == ir::OpClass::Flow) {
        if (try_flow(b, row)) break;
        continue;
      }
      if (ir::is_ps1x(b.profile) && row.cls == ir::OpClass::Arith && b.rng.chance(0.15)) {
        if (b.accept(coissued_pair(b, row, *b.rng.pick(arith)))) break;
        continue;
      }
      if (b.accept(propose(b, row))) break;
    }
  }
}

namespace {

// The texture-matrix product of `row`'s family on stages m.. (pads, then the final row),
// each row reading stage n's result.
std::vector<ir::Instruction> texm_product(Builder& b, const ir::OpInfo& row, uint32_t m,
                                          uint32_t n) {
  const uint8_t rows = ir::texm_rows(row.op);
  if (m + rows > 4) return {};
  std::vector<const ir::OpInfo*> pads, finals;
  for (const ir::OpInfo* r : legal_rows(b.profile, ir::OpClass::Texture))
    if (ir::texm_rows(r->op) == rows) (ir::is_texm_pad(r->op) ? pads : finals).push_back(r);
  if (pads.empty() || finals.empty()) return {};
  const ir::OpInfo& fin = ir::is_texm_pad(row.op) ? *b.rng.pick(finals) : row;
  std::vector<ir::Instruction> out;
  for (uint32_t j = 0; j + 1 < rows; ++j)
    out.push_back(
        make(pads[0]->op, dst_reg(RegFile::Texture, m + j), {src_reg(RegFile::Texture, n)}));
  ir::Instruction last =
      make(fin.op, dst_reg(RegFile::Texture, m + rows - 1u), {src_reg(RegFile::Texture, n)});
  if (fin.num_src > 1) last.src.push_back(src_reg(RegFile::Const, b.rng.below(8)));
  out.push_back(last);
  return out;
}

// One ps_1_1..1_3 texture instruction (or product) on stage m.
std::vector<ir::Instruction> texture_block(Builder& b, const ir::OpInfo& row, uint32_t m) {
  std::vector<uint32_t> sources;
  for (uint32_t n = 0; n < m; ++n)
    if (b.readable(RegFile::Texture, n)) sources.push_back(n);
  if (row.num_src == 0) return {make(row.op, dst_reg(RegFile::Texture, m))};
  if (sources.empty()) return {};
  const uint32_t n = b.rng.pick(sources);
  if (ir::texm_rows(row.op)) return texm_product(b, row, m, n);
  ir::SrcOperand s = src_reg(RegFile::Texture, n);
  if (b.rng.chance(0.15)) s.mod = ir::SrcMod::Bx2;
  return {make(row.op, dst_reg(RegFile::Texture, m), {s})};
}

// ps_1_4 texld / texcrd coordinate: t# (or, in the second phase, a temp), with the
// selectors and divides the profile has.
ir::SrcOperand ps14_coordinate(Builder& b, bool second_phase) {
  ir::SrcOperand s = src_reg(RegFile::Texture, b.rng.below(6));
  if (second_phase && b.rng.chance(0.5)) {
    if (auto r = random_source(b, ir::OperandKind::Vector, {RegFile::Temp}))
      s = src_reg(RegFile::Temp, r->index);
  }
  const uint8_t selectors[] = {ir::kIdentitySwizzle, ir::make_swizzle(0, 1, 2, 2),
                               ir::make_swizzle(0, 1, 3, 3)};
  s.swizzle = selectors[b.rng.below(3)];
  const ir::SrcMod mods[] = {ir::SrcMod::None, ir::SrcMod::None, ir::SrcMod::Dz, ir::SrcMod::Dw};
  s.mod = mods[b.rng.below(4)];
  return s;
}

} // namespace

void texture_stages_ps11_13(Builder& b) {
  const auto rows = legal_rows(b.profile, ir::OpClass::Texture);
  for (uint32_t m = 0; m < 4;) {
    bool placed = false;
    for (int attempt = 0; attempt < 8 && !b.rng.chance(0.1); ++attempt) {
      std::vector<ir::Instruction> block = texture_block(b, *b.rng.pick(rows), m);
      if (b.accept(block)) {
        m += static_cast<uint32_t>(block.size());
        placed = true;
        break;
      }
    }
    if (!placed) ++m;
  }
}

void texture_section_ps14(Builder& b, bool second_phase) {
  const auto rows = legal_rows(b.profile, ir::OpClass::Texture);
  const uint32_t count = 1 + b.rng.below(3);
  for (uint32_t i = 0; i < count; ++i)
    for (int attempt = 0; attempt < 8; ++attempt) {
      const ir::OpInfo& row = *b.rng.pick(rows);
      ir::Instruction ins = make(row.op, dst_reg(RegFile::Temp, b.rng.below(6)));
      if (row.op == Opcode::TexDepth) ins.dst = dst_reg(RegFile::Temp, 5);
      if (row.op == Opcode::TexKill && b.rng.chance(0.5))
        ins.dst = dst_reg(RegFile::Texture, b.rng.below(6));
      if (row.op == Opcode::TexCrd && b.rng.chance(0.5))
        ins.dst->mask = b.rng.chance(0.5) ? 0x3 : 0x7;
      if (row.num_src) ins.src.push_back(ps14_coordinate(b, second_phase));
      if (b.accept({ins})) break;
    }
}

} // namespace tierlift::gen::detail
