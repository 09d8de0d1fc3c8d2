// Profile legality of every opcode in every profile, against expectations written by hand
// from the ISA documents (docs/d3d9-rules.md §5.1–5.8: the per-instruction version columns and the
// availability matrix, which follow the Direct3D 9 instruction pages and vkd3d's tables) —
// a table of its own, NOT the validator's opcode table. Each row is parsed once in a
// profile where it exists, then validated against all seven profiles: where the
// expectation says "no", the validator must say not-in-profile at the instruction; where
// it says yes, it must not.
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

// One statement per row, written by hand from docs/d3d9-rules.md §5.
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
      {Opcode::SinCos3, {Profile::vs_3_0, "sincos r0.xy, r1.x"}},
      {Opcode::Break, {Profile::vs_2_x, "break"}},
      {Opcode::BreakGt, {Profile::vs_2_x, "break_gt r0.x, r1.x"}},
      {Opcode::BreakEq, {Profile::vs_2_x, "break_eq r0.x, r1.x"}},
      {Opcode::BreakGe, {Profile::vs_2_x, "break_ge r0.x, r1.x"}},
      {Opcode::BreakLt, {Profile::vs_2_x, "break_lt r0.x, r1.x"}},
      {Opcode::BreakNe, {Profile::vs_2_x, "break_ne r0.x, r1.x"}},
      {Opcode::BreakLe, {Profile::vs_2_x, "break_le r0.x, r1.x"}},
      {Opcode::BreakP, {Profile::vs_2_x, "breakp p0.x"}},
      {Opcode::IfGt, {Profile::vs_2_x, "if_gt r0.x, r1.x"}},
      {Opcode::IfEq, {Profile::vs_2_x, "if_eq r0.x, r1.x"}},
      {Opcode::IfGe, {Profile::vs_2_x, "if_ge r0.x, r1.x"}},
      {Opcode::IfLt, {Profile::vs_2_x, "if_lt r0.x, r1.x"}},
      {Opcode::IfNe, {Profile::vs_2_x, "if_ne r0.x, r1.x"}},
      {Opcode::IfLe, {Profile::vs_2_x, "if_le r0.x, r1.x"}},
      {Opcode::SetpGt, {Profile::vs_2_x, "setp_gt p0, r0, r1"}},
      {Opcode::SetpEq, {Profile::vs_2_x, "setp_eq p0, r0, r1"}},
      {Opcode::SetpGe, {Profile::vs_2_x, "setp_ge p0, r0, r1"}},
      {Opcode::SetpLt, {Profile::vs_2_x, "setp_lt p0, r0, r1"}},
      {Opcode::SetpNe, {Profile::vs_2_x, "setp_ne p0, r0, r1"}},
      {Opcode::SetpLe, {Profile::vs_2_x, "setp_le p0, r0, r1"}},
      {Opcode::TexLdL, {Profile::vs_3_0, "texldl r0, v0, s0"}},
      {Opcode::TexLdD, {Profile::ps_2_x, "texldd r0, t0, s0, r1, r2"}},
      {Opcode::Dsx, {Profile::ps_2_x, "dsx r0, r1"}},
      {Opcode::Dsy, {Profile::ps_2_x, "dsy r0, r1"}},
  };
  return s;
}

// One character per profile, in the order vs_1_1 vs_2_0 ps_1_1 ps_1_2 ps_1_3 ps_1_4 ps_2_0
// vs_2_x ps_2_x vs_3_0 ps_3_0: 'x' the instruction exists there, '.' it does not. The last
// four columns are the instruction lists of the 2.x and 3.0 reference pages (§14): ps_2_x
// adds static flow control, i#/b#, break/if comparisons, setp and the gradient
// instructions; loop and aL are 3.0 and vertex only; texldl is 3.0's.
const std::map<Opcode, const char*>& expected_legality() {
  static const std::map<Opcode, const char*> t = {
      // §5.1: in every profile (nop costs 0 slots in ps_1_x but exists)
      {Opcode::Nop, "xxxxxxxxxxx"},
      {Opcode::Mov, "xxxxxxxxxxx"},
      {Opcode::Add, "xxxxxxxxxxx"},
      {Opcode::Sub, "xxxxxxxxxxx"},
      {Opcode::Mul, "xxxxxxxxxxx"},
      {Opcode::Mad, "xxxxxxxxxxx"},
      {Opcode::Dp3, "xxxxxxxxxxx"},
      // §5.1: dp4 is missing from ps_1_1 only; lrp from vs_1_1 only
      {Opcode::Dp4, "xx.xxxxxxxx"},
      {Opcode::Lrp, ".xxxxxxxxxx"},
      // §5.1: vertex profiles and ps_2_0, no ps_1_x
      {Opcode::Min, "xx....xxxxx"},
      {Opcode::Max, "xx....xxxxx"},
      {Opcode::Rcp, "xx....xxxxx"},
      {Opcode::Rsq, "xx....xxxxx"},
      {Opcode::Exp, "xx....xxxxx"},
      {Opcode::Log, "xx....xxxxx"},
      {Opcode::Frc, "xx....xxxxx"},
      {Opcode::M4x4, "xx....xxxxx"},
      {Opcode::M4x3, "xx....xxxxx"},
      {Opcode::M3x4, "xx....xxxxx"},
      {Opcode::M3x3, "xx....xxxxx"},
      {Opcode::M3x2, "xx....xxxxx"},
      // §5.1: shader model 2 only
      {Opcode::Abs, ".x....xxxxx"},
      {Opcode::Crs, ".x....xxxxx"},
      {Opcode::Nrm, ".x....xxxxx"},
      {Opcode::Pow, ".x....xxxxx"},
      {Opcode::SinCos, ".x....xxx.."},
      // §5.2: vertex only (ps_2_0 has no sge, slt, dst, lit, expp, logp)
      {Opcode::Slt, "xx.....x.x."},
      {Opcode::Sge, "xx.....x.x."},
      {Opcode::Dst, "xx.....x.x."},
      {Opcode::Lit, "xx.....x.x."},
      {Opcode::Expp, "xx.....x.x."},
      {Opcode::Logp, "xx.....x.x."},
      {Opcode::Mova, ".x.....x.x."},
      {Opcode::Sgn, ".x.....x.x."},
      // §5.4: pixel arithmetic
      {Opcode::Cnd, "..xxxx....."},
      {Opcode::Cmp, "...xxxx.x.x"},
      {Opcode::Bem, ".....x....."},
      {Opcode::Dp2Add, "......x.x.x"},
      // §5.3: vs_2_0 static flow control; §5.4: phase is ps_1_4's
      {Opcode::Call, ".x.....xxxx"},
      {Opcode::CallNz, ".x.....xxxx"},
      {Opcode::Loop, ".x.....x.xx"},
      {Opcode::Ret, ".x.....xxxx"},
      {Opcode::EndLoop, ".x.....x.xx"},
      {Opcode::Label, ".x.....xxxx"},
      {Opcode::Rep, ".x.....xxxx"},
      {Opcode::EndRep, ".x.....xxxx"},
      {Opcode::If, ".x.....xxxx"},
      {Opcode::Else, ".x.....xxxx"},
      {Opcode::EndIf, ".x.....xxxx"},
      {Opcode::Phase, ".....x....."},
      // §5.5: ps_1_1–ps_1_3 texture addressing (texreg2gb: the instruction table and vkd3d
      // say from ps_1_1; one doc page says 1_2, a conflict §5.5 settles for 1_1)
      {Opcode::Tex, "..xxx......"},
      {Opcode::TexCoord, "..xxx......"},
      {Opcode::TexBem, "..xxx......"},
      {Opcode::TexBemL, "..xxx......"},
      {Opcode::TexReg2Ar, "..xxx......"},
      {Opcode::TexReg2Gb, "..xxx......"},
      {Opcode::TexM3x2Pad, "..xxx......"},
      {Opcode::TexM3x2Tex, "..xxx......"},
      {Opcode::TexM3x3Pad, "..xxx......"},
      {Opcode::TexM3x3Tex, "..xxx......"},
      {Opcode::TexM3x3Spec, "..xxx......"},
      {Opcode::TexM3x3VSpec, "..xxx......"},
      {Opcode::TexReg2Rgb, "...xx......"},
      {Opcode::TexDp3, "...xx......"},
      {Opcode::TexDp3Tex, "...xx......"},
      {Opcode::TexM3x3, "...xx......"},
      {Opcode::TexM3x2Depth, "....x......"},
      // texkill: ps_1_1–1_3 (§5.5), ps_1_4 (§5.6), ps_2_0 (§5.7)
      {Opcode::TexKill, "..xxxxx.x.x"},
      // §5.6: ps_1_4 texture instructions
      {Opcode::TexLd14, ".....x....."},
      {Opcode::TexCrd, ".....x....."},
      {Opcode::TexDepth, ".....x....."},
      // §5.7: ps_2_0 texture instructions
      {Opcode::TexLd, "......x.x.x"},
      {Opcode::TexLdP, "......x.x.x"},
      {Opcode::TexLdB, "......x.x.x"},
      // §5.8 / §1.4: dcl in vs_1_1, vs_2_0, ps_2_0; def everywhere; defi/defb vs_2_0
      {Opcode::Dcl, "xx....xxxxx"},
      {Opcode::Def, "xxxxxxxxxxx"},
      {Opcode::DefI, ".x.....xxxx"},
      {Opcode::DefB, ".x.....xxxx"},
      // §14: the 2.x / 3.0 instructions
      {Opcode::SinCos3, ".........xx"},
      {Opcode::Break, ".......xxxx"},
      {Opcode::BreakGt, ".......xxxx"},
      {Opcode::BreakEq, ".......xxxx"},
      {Opcode::BreakGe, ".......xxxx"},
      {Opcode::BreakLt, ".......xxxx"},
      {Opcode::BreakNe, ".......xxxx"},
      {Opcode::BreakLe, ".......xxxx"},
      {Opcode::BreakP, ".......xxxx"},
      {Opcode::IfGt, ".......xxxx"},
      {Opcode::IfEq, ".......xxxx"},
      {Opcode::IfGe, ".......xxxx"},
      {Opcode::IfLt, ".......xxxx"},
      {Opcode::IfNe, ".......xxxx"},
      {Opcode::IfLe, ".......xxxx"},
      {Opcode::SetpGt, ".......xxxx"},
      {Opcode::SetpEq, ".......xxxx"},
      {Opcode::SetpGe, ".......xxxx"},
      {Opcode::SetpLt, ".......xxxx"},
      {Opcode::SetpNe, ".......xxxx"},
      {Opcode::SetpLe, ".......xxxx"},
      {Opcode::TexLdL, ".........xx"},
      {Opcode::TexLdD, "........x.x"},
      {Opcode::Dsx, "........x.x"},
      {Opcode::Dsy, "........x.x"},
  };
  return t;
}

bool expected_legal(Opcode op, Profile p) {
  return expected_legality().at(op)[ir::profile_index(p)] == 'x';
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

TEST(ValidatorOpcodeTable, EveryOpcodeHasAnExpectation) {
  EXPECT_EQ(expected_legality().size(), static_cast<size_t>(ir::kOpcodeCount));
  for (const auto& [op, row] : expected_legality())
    EXPECT_EQ(std::string(row).size(), static_cast<size_t>(ir::kProfileCount)) << row;
  for (const ir::OpInfo& info : ir::opcode_table())
    EXPECT_TRUE(expected_legality().count(info.op)) << info.mnemonic;
}

TEST(ValidatorOpcodeTable, RowsAreRejectedExactlyWhereTheDocumentsSayNo) {
  int rejected = 0, accepted = 0;
  for (const ir::OpInfo& info : ir::opcode_table()) {
    auto it = samples().find(info.op);
    if (it == samples().end() || !expected_legality().count(info.op)) continue;
    const Sample& s = it->second;
    ASSERT_TRUE(expected_legal(info.op, s.profile)) << info.mnemonic;
    std::string text = std::string(ir::profile_name(s.profile)) + "\n" + s.text + "\n";
    for (Profile target : ir::kAllProfiles) {
      SCOPED_TRACE(std::string(info.mnemonic) + " validated as " +
                   std::string(ir::profile_name(target)));
      vtest::Run r = vtest::run(text, target);
      ASSERT_TRUE(r.parsed.program) << vtest::dump(r);
      ASSERT_EQ(r.parsed.program->code.size() + r.parsed.program->decls.size() +
                    r.parsed.program->defs.size(),
                1u);
      const bool legal = expected_legal(info.op, target);
      EXPECT_EQ(not_in_profile_at_line2(r), !legal) << vtest::dump(r);
      if (!legal) {
        ++rejected;
        EXPECT_FALSE(r.valid);
      } else {
        ++accepted;
      }
    }
  }
  // Every cell of the expectation table was checked, each once.
  int x_cells = 0, dot_cells = 0;
  for (const auto& [op, row] : expected_legality())
    for (const char* c = row; *c; ++c) (*c == 'x' ? x_cells : dot_cells)++;
  EXPECT_EQ(accepted, x_cells);
  EXPECT_EQ(rejected, dot_cells);
}

TEST(ValidatorOpcodeTable, MessageNamesWhereTheInstructionExists) {
  EXPECT_TRUE(vtest::has_error("ps_1_3\ntexld r0, t0\nmov r0, c0\n", "not-in-profile", 2, 1,
                               {"texld is not available in ps_1_3; it exists in ps_1_4, ps_2_0"}));
  EXPECT_TRUE(vtest::has_error("vs_1_1\nmov oPos, c0\nif b0\nendif\n", "not-in-profile", 3, 1,
                               {"if is not available in vs_1_1; it exists in vs_2_0"}));
}

} // namespace
