// Instruction-slot limits (docs/d3d9-rules.md §2): totals for vertex shaders; texture and
// arithmetic slots counted apart in pixel shaders (ps_1_4 per phase); macro sizes and
// texbeml's extra arithmetic slot from the opcode table; a co-issued pair costs one slot.
#include "context.h"

namespace tierlift::assembly::detail {
namespace {

// Shader model 3.0: every device has 512 instruction slots, and Direct3D 9 lets a device
// offer more through MaxVertexShader30InstructionSlots / MaxPixelShader30InstructionSlots,
// up to 32768 (fxc compiles such programs). Past 512 a program is legal but not portable:
// a warning (an error under --strict); past 32768 it is an error.
constexpr int kSm3GuaranteedSlots = 512;
constexpr int kSm3MostSlots = 32768;

struct Counter {
  const char* what; // "instruction", "texture", "arithmetic"
  int limit;
  int guaranteed = 0; // > 0: the slots every device has, below `limit` (shader model 3.0)
  int used = 0;
  bool reported = false;
  bool warned = false;

  // Adds `cost` slots of `ins`; reports the first instruction that crosses the limit.
  void add(Ctx& c, const ir::Instruction& ins, int cost, const std::string& scope) {
    if (cost <= 0) return;
    int first = used + 1;
    used += cost;
    if (guaranteed > 0 && used > guaranteed && !warned && used <= limit) {
      warned = true;
      c.warning(ins.loc, "slot-limit",
                fmt::format("{} guarantees {} {} slots and this instruction reaches slot {}: the "
                            "program runs only on a device that offers more (its "
                            "Max{}Shader30InstructionSlots cap, at most {})",
                            c.pname(), guaranteed, what, used, c.vs() ? "Vertex" : "Pixel", limit));
    }
    if (used <= limit || reported || limit <= 0) return;
    reported = true;
    std::string which = cost == 1
                            ? fmt::format("this instruction is the {}", ordinal(first))
                            : fmt::format("this {} takes slots {}..{}", mnemonic(ins), first, used);
    c.error(ins.loc, "slot-limit",
            fmt::format("{} allows {} {} slots{}; {}", c.pname(), limit, what, scope, which));
  }
};

// The instruction-slot counter of the target (shader model 3.0: guaranteed and most slots).
Counter instruction_counter(const Ctx& c) {
  if (c.sm3()) return Counter{"instruction", kSm3MostSlots, kSm3GuaranteedSlots};
  return Counter{"instruction", c.lim.max_slots};
}

void check_vertex(Ctx& c) {
  Counter total = instruction_counter(c);
  for (const ir::Instruction& ins : c.prog.code) total.add(c, ins, slot_cost(ins, c.target), "");
}

void check_pixel(Ctx& c) {
  Counter tex{"texture", c.lim.max_tex_slots}, arith{"arithmetic", c.lim.max_arith_slots};
  Counter total = instruction_counter(c);
  int phase = 1;
  bool has_phase = false;
  for (const ir::Instruction& ins : c.prog.code) has_phase |= ins.op == ir::Opcode::Phase;
  auto scope = [&]() {
    if (!c.ps14()) return std::string();
    return fmt::format(" per phase (this is phase {})", has_phase ? phase : 2);
  };
  for (const ir::Instruction& ins : c.prog.code) {
    if (ins.op == ir::Opcode::Phase) {
      tex = Counter{"texture", c.lim.max_tex_slots};
      arith = Counter{"arithmetic", c.lim.max_arith_slots};
      ++phase;
      continue;
    }
    // The second half of a co-issued pair shares its partner's slot (ps_1_x only; co-issue
    // elsewhere is reported by the coissue rule).
    if (ins.coissue && c.ps1x()) continue;
    int cost = slot_cost(ins, c.target);
    if (is_texture_op(ins)) {
      tex.add(c, ins, cost, scope());
      arith.add(c, ins, info_of(ins).extra_arith, scope());
    } else if (is_arith_op(ins)) {
      arith.add(c, ins, cost, scope());
    }
    if (c.ps2up()) total.add(c, ins, cost + info_of(ins).extra_arith, "");
  }
}

// ps_1_2/1_3: at most 3 cmp and 4 dp4 per shader (docs/d3d9-rules.md §5.1, §5.4).
void check_counts(Ctx& c) {
  if (c.target != ir::Profile::ps_1_2 && c.target != ir::Profile::ps_1_3) return;
  int cmp = 0, dp4 = 0;
  for (const ir::Instruction& ins : c.prog.code) {
    if (ins.op == ir::Opcode::Cmp && ++cmp == 4)
      c.error(ins.loc, "slot-limit",
              fmt::format("{} allows 3 cmp instructions; this is the 4th", c.pname()));
    if (ins.op == ir::Opcode::Dp4 && ++dp4 == 5)
      c.error(ins.loc, "slot-limit",
              fmt::format("{} allows 4 dp4 instructions; this is the 5th", c.pname()));
  }
}

} // namespace

void check_slots(Ctx& c) {
  if (c.vs())
    check_vertex(c);
  else
    check_pixel(c);
  check_counts(c);
}

} // namespace tierlift::assembly::detail
