// The validator's driver: one pass per rule family (each in its own rules_*.cpp), all
// diagnostics collected in one run, plus the small helpers the rule files share.
#include "tierlift/assembly/validator.h"

#include <algorithm>
#include <tuple>
#include <vector>

#include "context.h"

namespace tierlift::assembly {

bool validate(const ir::Program& program, ir::Profile target, ir::DiagnosticSink& diags,
              const ValidateOptions& options) {
  // Rules run family by family; their findings are handed on in source order, as a
  // compiler reports them.
  ir::DiagnosticSink local;
  const ir::Caps2x caps = options.caps.value_or(ir::default_caps(target));
  // The 2.x caps narrow the profile's largest counts (NumTemps, NumInstructionSlots).
  ir::ProfileLimits lim = ir::limits(target);
  if (ir::is_sm2x(target)) {
    lim.temps = caps.temps;
    lim.max_slots = caps.slots;
    if (target == ir::Profile::ps_2_x && !caps.no_texture_limit) lim.max_tex_slots = 32;
  }
  {
    detail::Ctx all{program, target, lim, local, options, caps, {}};
    detail::check_legality(all);
  }
  // Every other rule looks only at instructions the profile has: an instruction that does
  // not exist there is reported once (not-in-profile), not again for each operand.
  ir::Program legal = program;
  std::erase_if(legal.code, [&](const ir::Instruction& ins) {
    const ir::OpInfo& info = detail::info_of(ins);
    return info.cls == ir::OpClass::Decl || !ir::legal_in(info, target);
  });
  if (!ir::legal_in(ir::op_info(ir::Opcode::Dcl), target)) legal.decls.clear();
  std::erase_if(legal.defs, [&](const ir::ConstDef& d) {
    return d.file != ir::RegFile::Const && !ir::legal_in(ir::op_info(ir::Opcode::DefI), target);
  });
  detail::Ctx c{legal, target, lim, local, options, caps, {}};
  detail::check_registers(c);
  detail::check_declarations(c);
  detail::check_order(c);
  detail::check_slots(c);
  detail::check_modifiers(c);
  detail::check_masks(c);
  detail::check_special(c);
  detail::check_coissue(c);
  detail::check_texture_ops(c);
  detail::check_flow(c);
  detail::check_call_nesting(c);
  detail::check_dataflow(c);
  detail::check_outputs(c);
  detail::check_later(c);
  detail::check_gradients(c);
  std::vector<ir::Diagnostic> found = local.all();
  std::stable_sort(found.begin(), found.end(),
                   [](const ir::Diagnostic& a, const ir::Diagnostic& b) {
                     return std::tie(a.loc.file, a.loc.line, a.loc.col) <
                            std::tie(b.loc.file, b.loc.line, b.loc.col);
                   });
  for (ir::Diagnostic& d : found) diags.add(std::move(d));
  return !local.has_errors();
}

namespace detail {

const ir::OpInfo& info_of(const ir::Instruction& ins) {
  int i = static_cast<int>(ins.op);
  if (i < 0 || i >= ir::kOpcodeCount) return ir::op_info(ir::Opcode::Nop);
  return ir::op_info(ins.op);
}

std::string_view mnemonic(const ir::Instruction& ins) {
  return info_of(ins).mnemonic;
}

int slot_cost(const ir::Instruction& ins, ir::Profile p) {
  int s = info_of(ins).slots[ir::profile_index(p)];
  return s < 0 ? 0 : s;
}

bool is_texture_op(const ir::Instruction& ins) {
  return info_of(ins).cls == ir::OpClass::Texture;
}
bool is_arith_op(const ir::Instruction& ins) {
  return info_of(ins).cls == ir::OpClass::Arith;
}

std::string ordinal(size_t n) {
  const char* suf = "th";
  if (n % 100 < 11 || n % 100 > 13) {
    if (n % 10 == 1)
      suf = "st";
    else if (n % 10 == 2)
      suf = "nd";
    else if (n % 10 == 3)
      suf = "rd";
  }
  return fmt::format("{}{}", n, suf);
}

std::string reg_name(ir::RegFile f, uint32_t index) {
  return ir::register_name(f, index);
}

std::string mask_name(uint8_t mask) {
  static constexpr char names[] = "xyzw";
  std::string s = ".";
  for (int i = 0; i < 4; ++i)
    if (mask & (1 << i)) s += names[i];
  return s;
}

std::string reg_comps(ir::RegFile f, uint32_t index, uint8_t mask) {
  return reg_name(f, index) + mask_name(mask);
}

std::string swizzle_name(uint8_t swz) {
  static constexpr char names[] = "xyzw";
  std::string s = ".";
  for (int i = 0; i < 4; ++i) s += names[ir::swizzle_component(swz, i)];
  return s;
}

} // namespace detail
} // namespace tierlift::assembly
