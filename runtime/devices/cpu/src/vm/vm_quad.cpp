// 2x2 quads: the four invocations of a quad run each by itself up to its next gradient step
// (dsx, dsy), and then every lane waiting at one takes it together with the others, its source
// read in all four lanes before any of them writes. In flow that is the same for the whole quad
// (the only place where Direct3D 9 and Vulkan define a gradient) this is the lockstep a GPU
// runs: every lane reaches the same gradient with the same history. Where flow differs, a
// neighbour that is elsewhere (at another gradient, or ended) lends the value its register has
// there; the validator warns about such gradients (rule `gradient-in-divergent-flow`).
#include "vm_internal.h"

namespace tierlift::cpu::vm {
namespace {

// Runs inv until it ends or its next step is a gradient; true in the second case. `trace`:
// the steps it runs recorded there, when not null.
bool run_to_gradient(const Prepared& p, Invocation& inv, InstructionTrace* trace) {
  const Step* steps = p.steps.data();
  const auto n = static_cast<int32_t>(p.steps.size());
  while (inv.pc < n && !inv.stop) {
    const int32_t at = inv.pc;
    const Step& s = steps[at];
    if (s.gradient) return true;
    ++inv.pc;
    s.exec(s, inv);
    if (trace) record_step(p, inv, at, *trace);
  }
  return false;
}

} // namespace

void run_quad(const Prepared& p, Invocation* const (&lanes)[4], InstructionTrace* trace,
              int traced) {
  if (trace) start_trace(p, *trace);
  auto trace_of = [&](int l) { return l == traced ? trace : nullptr; };
  for (int l = 0; l < 4; ++l) {
    lanes[l]->lane = static_cast<uint8_t>(l);
    lanes[l]->in_quad = true;
  }
  for (;;) {
    bool waiting[4];
    bool any = false;
    for (int l = 0; l < 4; ++l) any |= waiting[l] = run_to_gradient(p, *lanes[l], trace_of(l));
    if (!any) return;
    // Every source is read before any lane writes (dsx r0, r0 in all four lanes).
    Vec4 quad[4][4];
    for (int l = 0; l < 4; ++l) {
      if (!waiting[l]) continue;
      const Step& s = p.steps[static_cast<size_t>(lanes[l]->pc)];
      for (int k = 0; k < 4; ++k) quad[l][k] = fetch(s.src[0], *lanes[k]);
    }
    for (int l = 0; l < 4; ++l) {
      if (!waiting[l]) continue;
      Invocation& inv = *lanes[l];
      const int32_t at = inv.pc++;
      const Step& s = p.steps[static_cast<size_t>(at)];
      inv.quad = quad[l];
      s.exec(s, inv);
      inv.quad = nullptr;
      if (InstructionTrace* t = trace_of(l)) record_step(p, inv, at, *t);
    }
  }
}

} // namespace tierlift::cpu::vm
