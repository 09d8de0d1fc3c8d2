// Shared state of one validation run: the program, the target profile and its limits, the
// sink, and small helpers every rule file uses (register names, ordinals, component sets).
#pragma once

#include <set>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "tierlift/assembly/validator.h"
#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/profile.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/semantics.h"

namespace tierlift::assembly::detail {

struct Ctx {
  const ir::Program& prog;
  ir::Profile target;
  const ir::ProfileLimits& lim; // the profile's limits with the caps' temps and slots
  ir::DiagnosticSink& sink;
  ValidateOptions opt;
  ir::Caps2x caps;                  // ValidateOptions::caps or ir::default_caps(target)
  std::set<uint32_t> warned_consts; // vertex c# past the guaranteed count, warned once

  std::string_view pname() const { return ir::profile_name(target); }
  bool vs() const { return ir::is_vertex(target); }
  bool ps11_13() const { return ir::is_ps11_13(target); }
  bool ps14() const { return target == ir::Profile::ps_1_4; }
  bool ps1x() const { return ir::is_ps1x(target); }
  // Pixel / vertex shader model 2.0 or later (2.0, 2.x, 3.0).
  bool ps2up() const { return !vs() && ir::is_sm2_or_later(target); }
  bool vs2up() const { return vs() && ir::is_sm2_or_later(target); }
  bool vs11() const { return target == ir::Profile::vs_1_1; }
  bool vs20() const { return target == ir::Profile::vs_2_0; }
  bool vs30() const { return target == ir::Profile::vs_3_0; }
  bool ps30() const { return target == ir::Profile::ps_3_0; }
  bool sm3() const { return ir::is_sm3(target); }

  void error(const ir::SourceLoc& loc, std::string_view rule, std::string msg) const {
    sink.error(loc, std::string(rule), std::move(msg));
  }
  void warning(const ir::SourceLoc& loc, std::string_view rule, std::string msg) const {
    if (opt.warnings) sink.warning(loc, std::string(rule), std::move(msg));
  }
};

// The table row of an instruction; never null (the IR only holds valid opcodes, but a
// corrupt value from a bytecode reader falls back to nop).
const ir::OpInfo& info_of(const ir::Instruction& ins);
std::string_view mnemonic(const ir::Instruction& ins);
// Slot cost of an instruction in the target (0 where it is not legal: that is reported
// separately as not-in-profile).
int slot_cost(const ir::Instruction& ins, ir::Profile p);
bool is_texture_op(const ir::Instruction& ins);
bool is_arith_op(const ir::Instruction& ins);

// "1st", "2nd", "9th".
std::string ordinal(size_t n);
// "r3", "c[a0.x + 4]", "-t1_bx2.xyz" is not needed: diagnostics name the register.
std::string reg_name(ir::RegFile f, uint32_t index);
// "r1.y", "r1.xz"
std::string reg_comps(ir::RegFile f, uint32_t index, uint8_t mask);
std::string mask_name(uint8_t mask);   // ".xz", ".xyzw" for full
std::string swizzle_name(uint8_t swz); // ".xyzw" for identity

// Coordinates a ps_2_0 texld reads through sampler s#: 2 for dcl_2d, else 3. (What an
// instruction reads and writes is ir::source_read_mask / ir::written_mask.)
int sampler_dim(const ir::Program& p, uint32_t index);

// One rule family per file.
void check_legality(Ctx& c);     // rules_legality.cpp: opcode in profile, operand count/kinds
void check_registers(Ctx& c);    // rules_registers.cpp
void check_declarations(Ctx& c); // rules_decls.cpp
void check_slots(Ctx& c);        // rules_slots.cpp
void check_order(Ctx& c);        // rules_order.cpp
void check_texture_ops(Ctx& c);  // rules_texops.cpp
void check_dataflow(Ctx& c);     // rules_dataflow.cpp
void check_outputs(Ctx& c);      // rules_outputs.cpp
void check_modifiers(Ctx& c);    // rules_modifiers.cpp
void check_masks(Ctx& c);        // rules_masks.cpp
void check_special(Ctx& c);      // rules_special.cpp (per-instruction operand rules)
void check_coissue(Ctx& c);      // rules_coissue.cpp
void check_flow(Ctx& c);         // rules_flow.cpp
void check_call_nesting(Ctx& c); // rules_calls.cpp (2.x and 3.0)
void check_later(Ctx& c);        // rules_later.cpp (2.x and 3.0: predicates, setp, o#, ...)
void check_gradients(Ctx& c);    // rules_gradients.cpp (dsx/dsy in flow that may diverge)

} // namespace tierlift::assembly::detail
