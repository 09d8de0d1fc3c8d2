// Iterates THE opcode table: each row is parsed once in a profile where it exists, then
// validated against all seven profiles. Where the row's `slots` column says "no", the
// validator must say not-in-profile at the instruction; where it says yes, it must not.
#include <map>

#include "tierlift/ir/opcodes.h"
#include "validator_test_util.h"

using namespace tierlift;
using ir::Opcode;
using ir::Profile;

namespace {

struct Sample {
  Profile profile;
  const char* text; // the statement, put on line 2 after the version line
};

// One statement per row, written by hand from d3d9-isa.md §5.
const std::map<Opcode, Sample>& samples() {
  static const std::map<Opcode, Sample> s = {
      {Opcode::Nop, {Profile::vs_1_1, "nop"}},
      {Opcode::Mov, {Profile::vs_1_1, "mov r0, r1"}},
      {Opcode::Add, {Profile::vs_1_1, "add r0, r1, r2"}},
      {Opcode::Sub, {Profile::vs_1_1, "sub r0, r1, r2"}},
      {Opcode::Mad, {Profile::vs_1_1, "mad r0, r1, r2, r3"}},
      {Opcode::Mul, {Profile::vs_1_1, "mul r0, r1, r2"}},
      {Opcode::Rcp, {Profile::vs_1_1, "rcp r0, r1.x"}},
      {Opcode::Rsq, {Profile::vs_1_1, "rsq r0, r1.x"}},
      {Opcode::Dp3, {Profile::vs_1_1, "dp3 r0, r1, r2"}},
      {Opcode::Dp4, {Profile::vs_1_1, "dp4 r0, r1, r2"}},
      {Opcode::Min, {Profile::vs_1_1, "min r0, r1, r2"}},
      {Opcode::Max, {Profile::vs_1_1, "max r0, r1, r2"}},
      {Opcode::Slt, {Profile::vs_1_1, "slt r0, r1, r2"}},
      {Opcode::Sge, {Profile::vs_1_1, "sge r0, r1, r2"}},
      {Opcode::Exp, {Profile::vs_1_1, "exp r0, r1.x"}},
      {Opcode::Log, {Profile::vs_1_1, "log r0, r1.x"}},
      {Opcode::Lit, {Profile::vs_1_1, "lit r0, r1"}},
      {Opcode::Dst, {Profile::vs_1_1, "dst r0, r1, r2"}},
      {Opcode::Lrp, {Profile::vs_2_0, "lrp r0, r1, r2, r3"}},
      {Opcode::Frc, {Profile::vs_2_0, "frc r0, r1"}},
      {Opcode::M4x4, {Profile::vs_1_1, "m4x4 r0, r1, c0"}},
      {Opcode::M4x3, {Profile::vs_1_1, "m4x3 r0.xyz, r1, c0"}},
      {Opcode::M3x4, {Profile::vs_1_1, "m3x4 r0, r1, c0"}},
      {Opcode::M3x3, {Profile::vs_1_1, "m3x3 r0.xyz, r1, c0"}},
      {Opcode::M3x2, {Profile::vs_1_1, "m3x2 r0.xy, r1, c0"}},
      {Opcode::Pow, {Profile::vs_2_0, "pow r0, r1.x, r2.x"}},
      {Opcode::Crs, {Profile::vs_2_0, "crs r0.xyz, r1, r2"}},
      {Opcode::Sgn, {Profile::vs_2_0, "sgn r0, r1, r2, r3"}},
      {Opcode::Abs, {Profile::vs_2_0, "abs r0, r1"}},
      {Opcode::Nrm, {Profile::vs_2_0, "nrm r0, r1"}},
      {Opcode::SinCos, {Profile::vs_2_0, "sincos r0.xy, r1.x, c0, c1"}},
      {Opcode::Mova, {Profile::vs_2_0, "mova a0.x, r0.x"}},
      {Opcode::Expp, {Profile::vs_1_1, "expp r0, r1.x"}},
      {Opcode::Logp, {Profile::vs_1_1, "logp r0, r1.x"}},
      {Opcode::Cnd, {Profile::ps_1_4, "cnd r0, r1, r2, r3"}},
      {Opcode::Cmp, {Profile::ps_2_0, "cmp r0, r1, r2, r3"}},
      {Opcode::Bem, {Profile::ps_1_4, "bem r0.xy, r1, r2"}},
      {Opcode::Dp2Add, {Profile::ps_2_0, "dp2add r0, r1, r2, r3.x"}},
      {Opcode::Call, {Profile::vs_2_0, "call l0"}},
      {Opcode::CallNz, {Profile::vs_2_0, "callnz l0, b0"}},
      {Opcode::Loop, {Profile::vs_2_0, "loop aL, i0"}},
      {Opcode::Ret, {Profile::vs_2_0, "ret"}},
      {Opcode::EndLoop, {Profile::vs_2_0, "endloop"}},
      {Opcode::Label, {Profile::vs_2_0, "label l0"}},
      {Opcode::Rep, {Profile::vs_2_0, "rep i0"}},
      {Opcode::EndRep, {Profile::vs_2_0, "endrep"}},
      {Opcode::If, {Profile::vs_2_0, "if b0"}},
      {Opcode::Else, {Profile::vs_2_0, "else"}},
      {Opcode::EndIf, {Profile::vs_2_0, "endif"}},
      {Opcode::Phase, {Profile::ps_1_4, "phase"}},
      {Opcode::Tex, {Profile::ps_1_1, "tex t0"}},
      {Opcode::TexLd14, {Profile::ps_1_4, "texld r0, t0"}},
      {Opcode::TexLd, {Profile::ps_2_0, "texld r0, t0, s0"}},
      {Opcode::TexLdP, {Profile::ps_2_0, "texldp r0, t0, s0"}},
      {Opcode::TexLdB, {Profile::ps_2_0, "texldb r0, t0, s0"}},
      {Opcode::TexCoord, {Profile::ps_1_1, "texcoord t0"}},
      {Opcode::TexCrd, {Profile::ps_1_4, "texcrd r0.xyz, t0"}},
      {Opcode::TexKill, {Profile::ps_1_1, "texkill t0"}},
      {Opcode::TexBem, {Profile::ps_1_1, "texbem t1, t0"}},
      {Opcode::TexBemL, {Profile::ps_1_1, "texbeml t1, t0"}},
      {Opcode::TexReg2Ar, {Profile::ps_1_1, "texreg2ar t1, t0"}},
      {Opcode::TexReg2Gb, {Profile::ps_1_1, "texreg2gb t1, t0"}},
      {Opcode::TexReg2Rgb, {Profile::ps_1_2, "texreg2rgb t1, t0"}},
      {Opcode::TexM3x2Pad, {Profile::ps_1_1, "texm3x2pad t1, t0"}},
      {Opcode::TexM3x2Tex, {Profile::ps_1_1, "texm3x2tex t2, t0"}},
      {Opcode::TexM3x2Depth, {Profile::ps_1_3, "texm3x2depth t2, t0"}},
      {Opcode::TexM3x3Pad, {Profile::ps_1_1, "texm3x3pad t1, t0"}},
      {Opcode::TexM3x3Tex, {Profile::ps_1_1, "texm3x3tex t3, t0"}},
      {Opcode::TexM3x3, {Profile::ps_1_2, "texm3x3 t3, t0"}},
      {Opcode::TexM3x3Spec, {Profile::ps_1_1, "texm3x3spec t3, t0, c0"}},
      {Opcode::TexM3x3VSpec, {Profile::ps_1_1, "texm3x3vspec t3, t0"}},
      {Opcode::TexDp3, {Profile::ps_1_2, "texdp3 t1, t0"}},
      {Opcode::TexDp3Tex, {Profile::ps_1_2, "texdp3tex t1, t0"}},
      {Opcode::TexDepth, {Profile::ps_1_4, "texdepth r5"}},
      {Opcode::Dcl, {Profile::vs_1_1, "dcl_position v0"}},
      {Opcode::Def, {Profile::ps_1_1, "def c0, 1, 0, 0, 1"}},
      {Opcode::DefI, {Profile::vs_2_0, "defi i0, 1, 0, 1, 0"}},
      {Opcode::DefB, {Profile::vs_2_0, "defb b0, true"}},
  };
  return s;
}

bool not_in_profile_at_line2(const vtest::Run& r) {
  for (const ir::Diagnostic& d : r.diags.all())
    if (d.rule == "not-in-profile" && d.loc.line == 2 && d.loc.col == 1 &&
        d.severity == ir::Severity::Error)
      return true;
  return false;
}

TEST(ValidatorOpcodeTable, EveryRowHasASample) {
  for (const ir::OpInfo& info : ir::opcode_table())
    EXPECT_TRUE(samples().count(info.op)) << info.mnemonic;
}

TEST(ValidatorOpcodeTable, RowsAreRejectedExactlyWhereTheTableSaysNo) {
  int rejected = 0;
  for (const ir::OpInfo& info : ir::opcode_table()) {
    auto it = samples().find(info.op);
    if (it == samples().end()) continue;
    const Sample& s = it->second;
    ASSERT_TRUE(ir::legal_in(info, s.profile)) << info.mnemonic;
    std::string text = std::string(ir::profile_name(s.profile)) + "\n" + s.text + "\n";
    for (Profile target : ir::kAllProfiles) {
      SCOPED_TRACE(std::string(info.mnemonic) + " validated as " +
                   std::string(ir::profile_name(target)));
      vtest::Run r = vtest::run(text, target);
      ASSERT_TRUE(r.parsed.program) << vtest::dump(r);
      ASSERT_EQ(r.parsed.program->code.size() + r.parsed.program->decls.size() +
                    r.parsed.program->defs.size(),
                1u);
      bool legal = ir::legal_in(info, target);
      EXPECT_EQ(not_in_profile_at_line2(r), !legal) << vtest::dump(r);
      if (!legal) {
        ++rejected;
        EXPECT_FALSE(r.valid);
      }
    }
  }
  // Every row but def (legal everywhere) is missing from some profile.
  EXPECT_GE(rejected, static_cast<int>(ir::opcode_table().size()) - 1);
}

TEST(ValidatorOpcodeTable, MessageNamesWhereTheInstructionExists) {
  EXPECT_TRUE(vtest::has_error("ps_1_3\ntexld r0, t0\nmov r0, c0\n", "not-in-profile", 2, 1,
                               {"texld is not available in ps_1_3; it exists in ps_1_4, ps_2_0"}));
  EXPECT_TRUE(vtest::has_error("vs_1_1\nmov oPos, c0\nif b0\nendif\n", "not-in-profile", 3, 1,
                               {"if is not available in vs_1_1; it exists in vs_2_0"}));
}

} // namespace
