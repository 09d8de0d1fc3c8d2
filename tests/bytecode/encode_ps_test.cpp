// Pixel-shader tokens derived by hand from the layout of docs/d3d9-rules.md §11.1/§11.2.
// Register type split: type bits 0-2 go to token bits 28-30, bits 3-4 to bits 11-12.
//   r = 0 → 0x0000_0000   v = 1 → 0x1000_0000   c = 2 → 0x2000_0000   t = 3 → 0x3000_0000
//   oC = 8 (0b01000) → lo 0, hi 1 → 0x0000_0800   s = 10 (0b01010) → 0x2000_0800
// Parameter tokens also set bit 31 (0x8000_0000). Identity swizzle .xyzw = 0xE4 in 16-23.
#include <gtest/gtest.h>

#include "hand_tokens_test.h"
#include "ir_build.h"

using namespace tierlift::test;
using tierlift::ir::Opcode;
using tierlift::ir::Profile;
using tierlift::ir::RegFile;

TEST(BytecodeHand, Ps20MovTexldDcl) {
  Builder b(Profile::ps_2_0);
  b.dcl_ps(RegFile::Texture, 0)
      .dcl_sampler(0, SamplerType::Tex2D)
      .ins(Opcode::TexLd, D(RegFile::Temp, 0), {S(RegFile::Texture, 0), S(RegFile::Sampler, 0)})
      .ins(Opcode::Mov, D(RegFile::ColorOut, 0), {S(RegFile::Temp, 0)});
  expect_tokens(b.p, {
                         0xFFFF0200, // ps_2_0: 0xFFFF0000 | 2<<8 | 0
                         // dcl t0: opcode 0x1F, length 2 in bits 24-27
                         0x0200001F,
                         0x80000000, // usage token: bit 31, usage 0 for ps_2_0 t#
                         0xB00F0000, // t0: 0x8000_0000 | type 3<<28 | mask F<<16
                         // dcl_2d s0
                         0x0200001F,
                         0x90000000, // bit 31 | texture type 2 << 27 (0x1000_0000)
                         0xA00F0800, // s0: 0x8000_0000 | 0x2000_0800 | mask F<<16
                         // texld r0, t0, s0: opcode 0x42, length 3
                         0x03000042,
                         0x800F0000, // r0, mask F
                         0xB0E40000, // t0, swizzle E4
                         0xA0E40800, // s0, swizzle E4
                         // mov oC0, r0: opcode 1, length 2
                         0x02000001,
                         0x800F0800, // oC0: type 8 → 0x800, mask F
                         0x80E40000, // r0
                         0x0000FFFF,
                     });
}

TEST(BytecodeHand, Ps20TexldpTexldbAndTexkill) {
  Builder b(Profile::ps_2_0);
  b.dcl_ps(RegFile::Texture, 1)
      .dcl_sampler(1, SamplerType::Cube)
      .dcl_sampler(2, SamplerType::Volume)
      .ins(Opcode::TexLdP, D(RegFile::Temp, 0), {S(RegFile::Texture, 1), S(RegFile::Sampler, 1)})
      .ins(Opcode::TexLdB, D(RegFile::Temp, 1), {S(RegFile::Texture, 1), S(RegFile::Sampler, 2)})
      .ins(Opcode::TexKill, D(RegFile::Temp, 1), {});
  expect_tokens(b.p, {
                         0xFFFF0200, 0x0200001F, 0x80000000,
                         0xB00F0001,             // dcl t1
                         0x0200001F, 0x98000000, // cube: 3<<27 = 0x1800_0000
                         0xA00F0801,             // s1
                         0x0200001F, 0xA0000000, // volume: 4<<27 = 0x2000_0000
                         0xA00F0802,             // s2
                         0x03010042,             // texldp: control 1 in bits 16-23
                         0x800F0000, 0xB0E40001, 0xA0E40801,
                         0x03020042, // texldb: control 2
                         0x800F0001, 0xB0E40001, 0xA0E40802,
                         0x01000041, // texkill: its operand is a destination token
                         0x800F0001, 0x0000FFFF,
                     });
}

TEST(BytecodeHand, Ps20ResultAndDeclModifiers) {
  Builder b(Profile::ps_2_0);
  b.dcl_ps(RegFile::Texture, 1, 0x3, Mods(false, 0, true))                 // dcl_pp t1.xy
      .dcl_ps(RegFile::Texture, 2, kFullMask, Mods(false, 0, false, true)) // dcl_centroid t2
      .dcl_ps(RegFile::Input, 0)                                           // dcl v0
      .ins(Opcode::Mul, D(RegFile::Temp, 0), {S(RegFile::Temp, 1), S(RegFile::Const, 0)},
           Mods(true)) // mul_sat r0, r1, c0
      .ins(Opcode::Mov, D(RegFile::ColorOut, 0), {S(RegFile::Temp, 0)}, Mods(false, 0, true));
  expect_tokens(b.p, {
                         0xFFFF0200,
                         0x0200001F,
                         0x80000000,
                         0xB0230001, // t1: mask 3<<16, result mod pp = 2<<20
                         0x0200001F,
                         0x80000000,
                         0xB04F0002, // t2: centroid = 4<<20
                         0x0200001F,
                         0x80000000,
                         0x900F0000, // v0: type 1
                         0x03000005,
                         0x801F0000, // r0 with sat = 1<<20
                         0x80E40001,
                         0xA0E40000,
                         0x02000001,
                         0x802F0800, // oC0 with pp = 2<<20
                         0x80E40000,
                         0x0000FFFF,
                     });
}

TEST(BytecodeHand, Ps20DefKeepsExactFloatBits) {
  Builder b(Profile::ps_2_0);
  // 1.0 = sign 0, exponent 127 (0x7F<<23), mantissa 0 → 0x3F800000
  // -0.5 = sign 1, exponent 126 → 0x80000000 | 0x3F000000 = 0xBF000000
  // 0.25 = exponent 125 → 0x3E800000; -0.0 = sign bit only = 0x80000000
  b.deff(3, 1.0f, -0.5f, 0.25f, -0.0f);
  // A quiet NaN with payload and a denormal survive unchanged as raw bits.
  b.def(RegFile::Const, 31, {0x7FC00123, 0x00000001, 0x7F800000, 0xFF800000});
  expect_tokens(b.p, {
                         0xFFFF0200,
                         0x05000051, // def: opcode 0x51, length 5
                         0xA00F0003, // c3: type 2<<28 | mask F
                         0x3F800000,
                         0xBF000000,
                         0x3E800000,
                         0x80000000,
                         0x05000051,
                         0xA00F001F,
                         0x7FC00123,
                         0x00000001,
                         0x7F800000,
                         0xFF800000,
                         0x0000FFFF,
                     });
}

TEST(BytecodeHand, Ps11CoissueShiftsAndSourceModifiers) {
  Builder b(Profile::ps_1_1);
  b.ins(Opcode::Tex, D(RegFile::Texture, 0), {})
      .ins(Opcode::TexCoord, D(RegFile::Texture, 1), {})
      // dp3_sat r0, t0_bx2, t1_bx2
      .ins(Opcode::Dp3, D(RegFile::Temp, 0),
           {S(RegFile::Texture, 0, kIdentitySwizzle, SrcMod::Bx2),
            S(RegFile::Texture, 1, kIdentitySwizzle, SrcMod::Bx2)},
           Mods(true))
      // mul_x2 r0.xyz, r0, -c0
      .ins(Opcode::Mul, D(RegFile::Temp, 0, 0x7),
           {S(RegFile::Temp, 0), S(RegFile::Const, 0, kIdentitySwizzle, SrcMod::Neg)},
           Mods(false, 1))
      // +add_d2 r0.w, 1-r1.w, -t1_bx2
      .ins(Opcode::Add, D(RegFile::Temp, 0, 0x8),
           {S(RegFile::Temp, 1, 0xFF, SrcMod::Comp),
            S(RegFile::Texture, 1, kIdentitySwizzle, SrcMod::Bx2Neg)},
           Mods(false, -1), true)
      // mul_x4 r1, r0_bias, v0.yzxw ; then d8 with the x2 source modifier
      .ins(Opcode::Mul, D(RegFile::Temp, 1),
           {S(RegFile::Temp, 0, kIdentitySwizzle, SrcMod::Bias),
            S(RegFile::Input, 0, make_swizzle(1, 2, 0, 3))},
           Mods(false, 2))
      .ins(Opcode::Mov, D(RegFile::Temp, 1, 0x5),
           {S(RegFile::Temp, 1, kIdentitySwizzle, SrcMod::X2)}, Mods(false, -3));
  expect_tokens(b.p, {
                         0xFFFF0101,
                         0x00000042, // tex: SM1, no length; destination only
                         0xB00F0000,
                         0x00000040, // texcoord t1
                         0xB00F0001,
                         0x00000008, // dp3
                         0x801F0000, // sat
                         0xB4E40000, // t0, bx2 = 4<<24
                         0xB4E40001, 0x00000005,
                         0x81070000, // mask xyz = 7, shift x2 = 1<<24
                         0x80E40000,
                         0xA1E40000, // -c0: neg = 1<<24
                         0x40000002, // co-issue bit 30
                         0x8F080000, // mask w = 8, shift d2 = -1 → 0xF<<24
                         0x86FF0001, // 1-r1.w: comp = 6, swizzle wwww = 0xFF
                         0xB5E40001, // -t1_bx2: bx2neg = 5
                         0x00000005,
                         0x820F0001, // x4 = 2<<24
                         0x82E40000, // bias = 2
                         0x90C90000, // v0.yzxw: 1 | 2<<2 | 0<<4 | 3<<6 = 0xC9
                         0x00000001,
                         0x8D050001, // d8 = -3 → 0xD, mask xz = 5
                         0x87E40001, // x2 source modifier = 7
                         0x0000FFFF,
                     });
}

TEST(BytecodeHand, Ps13Listing4ByHand) {
  // GPU Gems 21 Listing 4: tex t0..t3, then mul/mad with c0..c3.
  Builder b(Profile::ps_1_3);
  for (uint32_t i = 0; i < 4; ++i) b.ins(Opcode::Tex, D(RegFile::Texture, i), {});
  b.ins(Opcode::Mul, D(RegFile::Temp, 0), {S(RegFile::Texture, 0), S(RegFile::Const, 0)});
  for (uint32_t i = 1; i < 4; ++i)
    b.ins(Opcode::Mad, D(RegFile::Temp, 0),
          {S(RegFile::Texture, i), S(RegFile::Const, i), S(RegFile::Temp, 0)});
  expect_tokens(b.p, {
                         0xFFFF0103, 0x00000042, 0xB00F0000, 0x00000042, 0xB00F0001, 0x00000042,
                         0xB00F0002, 0x00000042, 0xB00F0003, 0x00000005, 0x800F0000, 0xB0E40000,
                         0xA0E40000, 0x00000004, 0x800F0000, 0xB0E40001, 0xA0E40001, 0x80E40000,
                         0x00000004, 0x800F0000, 0xB0E40002, 0xA0E40002, 0x80E40000, 0x00000004,
                         0x800F0000, 0xB0E40003, 0xA0E40003, 0x80E40000, 0x0000FFFF,
                     });
}

TEST(BytecodeHand, Ps14PhaseTexldTexcrd) {
  Builder b(Profile::ps_1_4);
  b.deff(0, 0.5f, 0.5f, 0.5f, 0.5f) // 0.5 = exponent 126 → 0x3F000000
      .ins(Opcode::TexCrd, D(RegFile::Temp, 1, 0x7), {S(RegFile::Texture, 1)})
      .ins(Opcode::TexLd14, D(RegFile::Temp, 0),
           {S(RegFile::Texture, 0, kIdentitySwizzle, SrcMod::Dz)})
      .ins(Opcode::Phase, std::nullopt, {})
      .ins(Opcode::TexLd14, D(RegFile::Temp, 2), {S(RegFile::Temp, 1)})
      .ins(Opcode::Mov, D(RegFile::Temp, 0), {S(RegFile::Temp, 2)});
  expect_tokens(b.p, {
                         0xFFFF0104,
                         0x00000051, // def in SM1: no length
                         0xA00F0000, 0x3F000000, 0x3F000000, 0x3F000000, 0x3F000000,
                         0x00000040, // texcrd r1.xyz, t1
                         0x80070001, 0xB0E40001,
                         0x00000042, // texld r0, t0_dz: one source in 1.4
                         0x800F0000,
                         0xB9E40000, // dz = 9<<24
                         0x0000FFFD, // phase
                         0x00000042, 0x800F0002, 0x80E40001, 0x00000001, 0x800F0000,
                         0x80E40002, 0x0000FFFF,
                     });
}
