// Co-issue ("+") legality (docs/d3d9-rules.md §4.6): ps_1_x only; two arithmetic halves, one
// writing colour (.rgb exactly in 1_1–1_3, a subset of .rgb in 1_4), the other alpha; no dp4, bem
// or texture instruction; dp3 only in the colour half.
#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;

constexpr uint8_t XYZ = 7, W = 8;

bool colour_mask(const Ctx& c, uint8_t m) {
  return c.ps14() ? (m != 0 && (m & W) == 0) : m == XYZ;
}

void check_half(Ctx& c, const ir::Instruction& ins) {
  if (!is_arith_op(ins) || ins.op == Opcode::Nop)
    c.error(
        ins.loc, "coissue",
        fmt::format("{} cannot be co-issued: only arithmetic instructions pair up", mnemonic(ins)));
  else if (ins.op == Opcode::Dp4)
    c.error(ins.loc, "coissue", "dp4 cannot be co-issued: it uses both the colour and alpha pipes");
  else if (ins.op == Opcode::Bem)
    c.error(ins.loc, "coissue", "bem cannot be co-issued");
}

void check_pair(Ctx& c, const ir::Instruction& a, const ir::Instruction& b) {
  check_half(c, a);
  check_half(c, b);
  if (!a.dst || !b.dst) return;
  uint8_t ma = a.dst->mask, mb = b.dst->mask;
  bool ok = (colour_mask(c, ma) && mb == W) || (ma == W && colour_mask(c, mb));
  if (!ok) {
    c.error(b.loc, "coissue",
            fmt::format("a co-issued pair needs one half writing {} and the other .a; these "
                        "write {} and {}",
                        c.ps14() ? "colour components (.rgb or a subset)" : ".rgb", mask_name(ma),
                        mask_name(mb)));
    return;
  }
  const ir::Instruction& alpha_half = ma == W ? a : b;
  if (alpha_half.op == Opcode::Dp3)
    c.error(alpha_half.loc, "coissue", "dp3 runs in the colour pipe; it cannot be the .a half");
}

} // namespace

void check_coissue(Ctx& c) {
  const auto& code = c.prog.code;
  for (size_t i = 0; i < code.size(); ++i) {
    const ir::Instruction& ins = code[i];
    if (!ins.coissue) continue;
    if (!c.ps1x()) {
      c.error(ins.loc, "coissue",
              fmt::format("co-issue (+) exists only in ps_1_1..ps_1_4, not in {}", c.pname()));
      continue;
    }
    if (i == 0 || code[i - 1].coissue || code[i - 1].op == Opcode::Phase) {
      c.error(ins.loc, "coissue",
              "a co-issued instruction (+) must follow the instruction it pairs with; a pair "
              "has two halves");
      continue;
    }
    check_pair(c, code[i - 1], ins);
  }
}

} // namespace tierlift::assembly::detail
