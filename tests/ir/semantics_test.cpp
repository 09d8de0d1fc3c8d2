// The opcode table's semantic columns (matrix rows, written components per profile, source
// lanes, sampling, implicit effects) and the read/write sets computed from them, against
// expectations written by hand from the instruction pages of the Direct3D 9 ISA.
#include <gtest/gtest.h>

#include "tierlift/ir/semantics.h"

using namespace tierlift;
using ir::Opcode;
using ir::Profile;

namespace {

constexpr uint8_t X = 1, Y = 2, Z = 4, W = 8;

// An instruction `op dst.mask, r1, r2, r3` (as many sources as the row takes).
ir::Instruction make(Opcode op, uint8_t mask = ir::kFullMask) {
  ir::Instruction ins;
  ins.op = op;
  ins.dst = ir::DstOperand{ir::RegFile::Temp, 0, mask, {}};
  for (uint8_t k = 0; k < ir::op_info(op).num_src; ++k) {
    ir::SrcOperand s;
    s.index = 1u + k;
    ins.src.push_back(s);
  }
  return ins;
}

TEST(Semantics, MatrixMacroRows) {
  EXPECT_EQ(ir::op_semantics(Opcode::M4x4).matrix_rows, 4);
  EXPECT_EQ(ir::op_semantics(Opcode::M4x3).matrix_rows, 3);
  EXPECT_EQ(ir::op_semantics(Opcode::M3x4).matrix_rows, 4);
  EXPECT_EQ(ir::op_semantics(Opcode::M3x3).matrix_rows, 3);
  EXPECT_EQ(ir::op_semantics(Opcode::M3x2).matrix_rows, 2);
  EXPECT_EQ(ir::op_semantics(Opcode::Dp4).matrix_rows, 0);
  // Only the matrix operand spans rows: m3x2 r0.xy, r1, c4 reads c4 and c5.
  const ir::Instruction m = make(Opcode::M3x2, X | Y);
  EXPECT_EQ(ir::source_rows(m, 0), 1u);
  EXPECT_EQ(ir::source_rows(m, 1), 2u);
  EXPECT_EQ(ir::source_rows(make(Opcode::Mad), 1), 1u);
}

TEST(Semantics, MatrixMacroLanesAndWrites) {
  // m3x2 writes .xy and reads .xyz of the vector and of each row; m4x3 reads xyzw, writes xyz.
  const ir::Instruction m32 = make(Opcode::M3x2);
  EXPECT_EQ(ir::written_mask(m32, Profile::vs_1_1), X | Y);
  EXPECT_EQ(ir::source_read_mask(m32, 0, Profile::vs_1_1, 3), X | Y | Z);
  EXPECT_EQ(ir::source_read_mask(m32, 1, Profile::vs_1_1, 3), X | Y | Z);
  const ir::Instruction m43 = make(Opcode::M4x3);
  EXPECT_EQ(ir::written_mask(m43, Profile::vs_2_0), X | Y | Z);
  EXPECT_EQ(ir::source_read_mask(m43, 0, Profile::vs_2_0, 3), X | Y | Z | W);
  EXPECT_EQ(ir::written_mask(make(Opcode::M3x4), Profile::ps_2_0), X | Y | Z | W);
}

TEST(Semantics, DotProductsReadFixedLanes) {
  // dp3 r0.x reads xyz of both sources, whatever the mask; dp4 xyzw; dp2add xy + scalar.
  const ir::Instruction dp3 = make(Opcode::Dp3, X);
  EXPECT_EQ(ir::source_read_mask(dp3, 0, Profile::vs_1_1, 3), X | Y | Z);
  EXPECT_EQ(ir::source_read_mask(dp3, 1, Profile::vs_1_1, 3), X | Y | Z);
  EXPECT_EQ(ir::source_read_mask(make(Opcode::Dp4, W), 1, Profile::vs_1_1, 3), X | Y | Z | W);
  ir::Instruction dp2 = make(Opcode::Dp2Add, X);
  dp2.src[2].swizzle = ir::replicate_swizzle(2); // r3.z
  EXPECT_EQ(ir::source_read_mask(dp2, 0, Profile::ps_2_0, 3), X | Y);
  EXPECT_EQ(ir::source_read_mask(dp2, 2, Profile::ps_2_0, 3), Z);
}

TEST(Semantics, PerComponentOpsFollowTheMaskThroughTheSwizzle) {
  // add r0.xz, r1.yxwz, r2: r1's .y and .w, r2's .x and .z.
  ir::Instruction add = make(Opcode::Add, X | Z);
  add.src[0].swizzle = ir::make_swizzle(1, 0, 3, 2);
  EXPECT_EQ(ir::source_read_mask(add, 0, Profile::vs_1_1, 3), Y | W);
  EXPECT_EQ(ir::source_read_mask(add, 1, Profile::vs_1_1, 3), X | Z);
  EXPECT_EQ(ir::written_mask(add, Profile::vs_1_1), X | Z);
}

TEST(Semantics, ScalarOpsReadTheirReplicateLane) {
  ir::Instruction rcp = make(Opcode::Rcp);
  rcp.src[0].swizzle = ir::replicate_swizzle(3); // r1.w
  EXPECT_EQ(ir::source_read_mask(rcp, 0, Profile::vs_1_1, 3), W);
  EXPECT_EQ(ir::written_mask(rcp, Profile::vs_1_1), X | Y | Z | W);
}

TEST(Semantics, WrittenComponentsPerProfile) {
  // frc in vs_1_1 is a macro writing .xy only; in vs_2_0 / ps_2_0 every masked component.
  const ir::Instruction frc = make(Opcode::Frc);
  EXPECT_EQ(ir::written_mask(frc, Profile::vs_1_1), X | Y);
  EXPECT_EQ(ir::written_mask(frc, Profile::vs_2_0), X | Y | Z | W);
  EXPECT_EQ(ir::source_read_mask(frc, 0, Profile::vs_1_1, 3), X | Y);
  // sincos writes the masked part of .xy (.z undefined, .w untouched).
  EXPECT_EQ(ir::written_mask(make(Opcode::SinCos, X | Y), Profile::vs_2_0), X | Y);
  EXPECT_EQ(ir::written_mask(make(Opcode::SinCos, Y), Profile::ps_2_0), Y);
  EXPECT_EQ(ir::written_mask(make(Opcode::Crs), Profile::vs_2_0), X | Y | Z);
  EXPECT_EQ(ir::written_mask(make(Opcode::Bem, X | Y), Profile::ps_1_4), X | Y);
}

TEST(Semantics, SpecialLaneRules) {
  // lit r0 reads .x, .y, .w; lit r0.y reads .x only.
  EXPECT_EQ(ir::source_read_mask(make(Opcode::Lit), 0, Profile::vs_1_1, 3), X | Y | W);
  EXPECT_EQ(ir::source_read_mask(make(Opcode::Lit, Y), 0, Profile::vs_1_1, 3), X);
  // dst r0: src0 .y .z, src1 .y .w.
  EXPECT_EQ(ir::source_read_mask(make(Opcode::Dst), 0, Profile::vs_1_1, 3), Y | Z);
  EXPECT_EQ(ir::source_read_mask(make(Opcode::Dst), 1, Profile::vs_1_1, 3), Y | W);
  // crs r0.x = s0.y*s1.z - s0.z*s1.y.
  EXPECT_EQ(ir::source_read_mask(make(Opcode::Crs, X), 0, Profile::vs_2_0, 3), Y | Z);
  // nrm r0.xyz reads xyz; sgn's scratch temps are not read.
  EXPECT_EQ(ir::source_read_mask(make(Opcode::Nrm, X), 0, Profile::ps_2_0, 3), X | Y | Z);
  EXPECT_EQ(ir::source_read_mask(make(Opcode::Sgn), 1, Profile::vs_2_0, 3), 0);
}

TEST(Semantics, TextureCoordinatesAndSampling) {
  // texld reads xy through a dcl_2d sampler, xyz through a cube; texldp adds .w.
  EXPECT_EQ(ir::source_read_mask(make(Opcode::TexLd), 0, Profile::ps_2_0, 2), X | Y);
  EXPECT_EQ(ir::source_read_mask(make(Opcode::TexLd), 0, Profile::ps_2_0, 3), X | Y | Z);
  EXPECT_EQ(ir::source_read_mask(make(Opcode::TexLdP), 0, Profile::ps_2_0, 2), X | Y | W);
  EXPECT_EQ(ir::source_read_mask(make(Opcode::TexReg2Ar), 0, Profile::ps_1_1, 3), X | W);
  EXPECT_EQ(ir::source_read_mask(make(Opcode::TexReg2Gb), 0, Profile::ps_1_1, 3), Y | Z);
  EXPECT_TRUE(ir::samples(make(Opcode::Tex)));
  EXPECT_TRUE(ir::samples(make(Opcode::TexM3x3VSpec)));
  EXPECT_TRUE(ir::samples(make(Opcode::TexLdB)));
  EXPECT_FALSE(ir::samples(make(Opcode::TexCoord)));
  EXPECT_FALSE(ir::samples(make(Opcode::TexM3x2Pad)));
  EXPECT_FALSE(ir::samples(make(Opcode::TexM3x3)));
  EXPECT_FALSE(ir::samples(make(Opcode::Mov)));
}

TEST(Semantics, TextureWritesAndImplicitEffects) {
  // A pad row leaves nothing readable; texcrd defines .xyz (.xy with _dw).
  EXPECT_EQ(ir::written_mask(make(Opcode::TexM3x3Pad), Profile::ps_1_1), 0);
  EXPECT_EQ(ir::written_mask(make(Opcode::TexKill), Profile::ps_2_0), 0);
  EXPECT_EQ(ir::written_mask(make(Opcode::Tex), Profile::ps_1_1), X | Y | Z | W);
  ir::Instruction crd = make(Opcode::TexCrd);
  EXPECT_EQ(ir::written_mask(crd, Profile::ps_1_4), X | Y | Z);
  crd.src[0].mod = ir::SrcMod::Dw;
  EXPECT_EQ(ir::written_mask(crd, Profile::ps_1_4), X | Y);
  EXPECT_TRUE(ir::has_implicit(make(Opcode::TexKill), ir::kDiscards));
  EXPECT_TRUE(ir::has_implicit(make(Opcode::TexDepth), ir::kWritesDepth));
  EXPECT_TRUE(ir::has_implicit(make(Opcode::TexM3x2Depth), ir::kWritesDepth));
  EXPECT_TRUE(ir::has_implicit(make(Opcode::Tex), ir::kReadsTexCoord));
  EXPECT_FALSE(ir::has_implicit(make(Opcode::TexReg2Ar), ir::kReadsTexCoord));
  EXPECT_TRUE(ir::has_implicit(make(Opcode::TexM3x3VSpec), ir::kReadsEyeFromRows));
  EXPECT_TRUE(ir::has_implicit(make(Opcode::Loop), ir::kWritesLoopCounter));
  EXPECT_TRUE(ir::has_implicit(make(Opcode::Mova), ir::kWritesAddress));
  EXPECT_FALSE(ir::has_implicit(make(Opcode::Mov), ir::kWritesAddress));
}

} // namespace

// The texm3x2* / texm3x3* family: every row names its product's size, the pads are marked,
// and no instruction outside the family claims a row (the validator's ordering rules, the
// interpreter's pad registers and the ps_1_1 _bx2 allowance all read these columns).
TEST(Semantics, TextureMatrixRows) {
  const struct {
    Opcode op;
    uint8_t rows;
    bool pad;
  } family[] = {
      {Opcode::TexM3x2Pad, 2, true},    {Opcode::TexM3x2Tex, 2, false},
      {Opcode::TexM3x2Depth, 2, false}, {Opcode::TexM3x3Pad, 3, true},
      {Opcode::TexM3x3Tex, 3, false},   {Opcode::TexM3x3, 3, false},
      {Opcode::TexM3x3Spec, 3, false},  {Opcode::TexM3x3VSpec, 3, false},
  };
  size_t members = 0;
  for (const auto& f : family) {
    SCOPED_TRACE(ir::op_info(f.op).mnemonic);
    EXPECT_EQ(ir::texm_rows(f.op), f.rows);
    EXPECT_EQ(ir::is_texm_pad(f.op), f.pad);
    EXPECT_EQ(ir::is_texm_final(f.op), !f.pad);
    // A pad defines nothing readable; every row reads TC(m), the final rows the pads too.
    EXPECT_EQ(ir::op_writes(f.op, Profile::ps_1_1) == 0, f.pad || f.op == Opcode::TexM3x2Depth);
    EXPECT_EQ(ir::op_semantics(f.op).implicit & ir::kReadsPadRows, f.pad ? 0 : ir::kReadsPadRows);
  }
  for (const ir::OpInfo& info : ir::opcode_table()) members += ir::texm_rows(info.op) != 0;
  EXPECT_EQ(members, std::size(family));
  EXPECT_EQ(ir::texm_rows(Opcode::TexDp3Tex), 0);
  EXPECT_FALSE(ir::is_texm_pad(Opcode::Tex));
}
