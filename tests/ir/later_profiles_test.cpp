// The four later profiles in the IR: names, version tokens, register types, the opcode
// table's rows for them (bytecode numbers from the published D3D9 encoding), and the
// execution guard that refuses them with a position.
#include <gtest/gtest.h>

#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/profile.h"
#include "tierlift/ir/registers.h"
#include "tierlift/ir/sm3_interface.h"

using namespace tierlift::ir;

TEST(LaterProfiles, NamesAndVersionTokens) {
  EXPECT_EQ(parse_profile("vs_2_x"), Profile::vs_2_x);
  EXPECT_EQ(parse_profile("ps.2.x"), Profile::ps_2_x);
  EXPECT_EQ(parse_profile("ps_2_X"), Profile::ps_2_x);
  EXPECT_EQ(parse_profile("vs.3.0"), Profile::vs_3_0);
  EXPECT_EQ(parse_profile("ps_3_0"), Profile::ps_3_0);
  EXPECT_FALSE(parse_profile("ps_2_a").has_value()); // a caps preset, not a profile
  EXPECT_EQ(version_token(Profile::vs_2_x), 0xFFFE0201u);
  EXPECT_EQ(version_token(Profile::ps_2_x), 0xFFFF0201u);
  EXPECT_EQ(version_token(Profile::vs_3_0), 0xFFFE0300u);
  EXPECT_EQ(version_token(Profile::ps_3_0), 0xFFFF0300u);
  EXPECT_EQ(profile_from_version_token(0xFFFF0300u), Profile::ps_3_0);
  EXPECT_TRUE(is_vertex(Profile::vs_3_0));
  EXPECT_TRUE(is_pixel(Profile::ps_2_x));
}

TEST(LaterProfiles, RegisterTypes) {
  EXPECT_EQ(bytecode_regtype(RegFile::Predicate), 19);
  EXPECT_EQ(bytecode_regtype(RegFile::Misc), 17);
  EXPECT_EQ(bytecode_regtype(RegFile::Output), 6);
  EXPECT_EQ(regfile_from_bytecode(6, Profile::vs_3_0), RegFile::Output);
  EXPECT_EQ(regfile_from_bytecode(6, Profile::vs_2_0), RegFile::TexCrdOut);
  EXPECT_EQ(regfile_from_bytecode(19, Profile::ps_3_0), RegFile::Predicate);
  EXPECT_EQ(register_name(RegFile::Misc, kMiscFace), "vFace");
  EXPECT_EQ(register_name(RegFile::Misc, kMiscPosition), "vPos");
  EXPECT_EQ(register_name(RegFile::Output, 11), "o11");
}

// Opcode and control numbers of the D3D9 encoding (d3d9types.h's D3DSIO_* values and the
// comparison codes gt 1, eq 2, ge 3, lt 4, ne 5, le 6).
TEST(LaterProfiles, NewRowsCarryThePublishedNumbers) {
  struct Pin {
    const char* mnemonic;
    Profile profile;
    uint16_t code;
    uint8_t control;
  };
  const Pin pins[] = {
      {"break", Profile::vs_2_x, 0x2C, 0},    {"break_gt", Profile::vs_2_x, 0x2D, 1},
      {"break_eq", Profile::vs_2_x, 0x2D, 2}, {"break_ge", Profile::ps_2_x, 0x2D, 3},
      {"break_lt", Profile::ps_3_0, 0x2D, 4}, {"break_ne", Profile::vs_3_0, 0x2D, 5},
      {"break_le", Profile::vs_3_0, 0x2D, 6}, {"breakp", Profile::ps_2_x, 0x60, 0},
      {"if_gt", Profile::vs_2_x, 0x29, 1},    {"if_eq", Profile::vs_2_x, 0x29, 2},
      {"if_ge", Profile::ps_2_x, 0x29, 3},    {"if_lt", Profile::ps_3_0, 0x29, 4},
      {"if_ne", Profile::vs_3_0, 0x29, 5},    {"if_le", Profile::vs_3_0, 0x29, 6},
      {"setp_gt", Profile::vs_2_x, 0x5E, 1},  {"setp_eq", Profile::vs_2_x, 0x5E, 2},
      {"setp_ge", Profile::ps_2_x, 0x5E, 3},  {"setp_lt", Profile::ps_3_0, 0x5E, 4},
      {"setp_ne", Profile::vs_3_0, 0x5E, 5},  {"setp_le", Profile::vs_3_0, 0x5E, 6},
      {"texldl", Profile::vs_3_0, 0x5F, 0},   {"texldd", Profile::ps_2_x, 0x5D, 0},
      {"dsx", Profile::ps_3_0, 0x5B, 0},      {"dsy", Profile::ps_3_0, 0x5C, 0},
      {"sincos", Profile::vs_3_0, 0x25, 0},   {"loop", Profile::ps_3_0, 0x1B, 0},
      {"defi", Profile::ps_2_x, 0x30, 0},     {"defb", Profile::ps_3_0, 0x2F, 0},
  };
  for (const Pin& p : pins) {
    SCOPED_TRACE(p.mnemonic);
    const OpInfo* row = find_opcode(p.mnemonic, p.profile);
    ASSERT_NE(row, nullptr);
    EXPECT_TRUE(legal_in(*row, p.profile));
    EXPECT_EQ(row->code, p.code);
    EXPECT_EQ(row->control, p.control);
    EXPECT_EQ(find_opcode_by_code(p.code, p.control, p.profile), row);
  }
  // sincos: three sources up to 2.x, one in 3.0.
  EXPECT_EQ(find_opcode("sincos", Profile::vs_2_x)->num_src, 3);
  EXPECT_EQ(find_opcode("sincos", Profile::ps_3_0)->num_src, 1);
  EXPECT_EQ(find_opcode("sincos", Profile::ps_3_0)->op, Opcode::SinCos3);
}

// Every value of fxc's three 2.x targets. Sources: the D3DX reference pages
// D3DXGetPixelShaderProfile and D3DXGetVertexShaderProfile (each target is ps_2_0 / vs_2_0
// plus the capabilities they list, and nothing else), and the published pixel-shader
// comparison tables for the 512 instruction slots of ps_2_a and ps_2_b.
TEST(LaterProfiles, CapsPresets) {
  auto a = caps_preset("ps_2_a"), b = caps_preset("ps_2_b"), v = caps_preset("vs_2_a");
  ASSERT_TRUE(a && b && v);
  // ps_2_a: r# >= 22, arbitrary swizzle, dsx/dsy, predication, no dependent-read limit, no
  // texture-instruction limit; flow control is not on its list (neither static nor dynamic).
  EXPECT_EQ(a->first, Profile::ps_2_x);
  EXPECT_EQ(a->second.temps, 22);
  EXPECT_EQ(a->second.slots, 512);
  EXPECT_EQ(a->second.static_depth, 0);
  EXPECT_EQ(a->second.dynamic_depth, 0);
  EXPECT_TRUE(a->second.predication);
  EXPECT_TRUE(a->second.gradients);
  EXPECT_TRUE(a->second.arbitrary_swizzle);
  EXPECT_TRUE(a->second.no_dependent_limit);
  EXPECT_TRUE(a->second.no_texture_limit);
  // ps_2_b: r# >= 32 and no texture-instruction limit, nothing else.
  EXPECT_EQ(b->first, Profile::ps_2_x);
  EXPECT_EQ(b->second.temps, 32);
  EXPECT_EQ(b->second.slots, 512);
  EXPECT_EQ(b->second.static_depth, 0);
  EXPECT_EQ(b->second.dynamic_depth, 0);
  EXPECT_FALSE(b->second.predication);
  EXPECT_FALSE(b->second.gradients);
  EXPECT_FALSE(b->second.arbitrary_swizzle);
  EXPECT_FALSE(b->second.no_dependent_limit);
  EXPECT_TRUE(b->second.no_texture_limit);
  // vs_2_a: r# >= 13, dynamic flow control (vs_2_x's one non-zero depth, 24), predication;
  // loop/rep and call nesting stay vs_2_0's 1 (the vertex nesting table: 1 to 4 by caps).
  EXPECT_EQ(v->first, Profile::vs_2_x);
  EXPECT_EQ(v->second.temps, 13);
  EXPECT_EQ(v->second.slots, 256);
  EXPECT_EQ(v->second.static_depth, 1);
  EXPECT_EQ(v->second.dynamic_depth, 24);
  EXPECT_TRUE(v->second.predication);
  EXPECT_FALSE(caps_preset("ps_2_c").has_value());
}

TEST(LaterProfiles, WhatDoesNotRunYetIsRefusedWithAPosition) {
  // 2.x and 3.0 run on both devices (mov, setp, ...), except what each error names: here
  // psize0 read by a pixel program (a vertex output only: NUMERICS.md F6). A predicated break
  // is not Direct3D 9 at all: validate_ir refuses it (PredicatedFlowControlIsNotDirect3D9).
  Program p;
  p.profile = Profile::ps_3_0;
  p.version_loc = {1, 1, 1, 6};
  Instruction mov;
  mov.op = Opcode::Mov;
  mov.loc = {1, 2, 1, 3};
  p.code.push_back(mov);
  Instruction setp;
  setp.op = Opcode::SetpLe;
  setp.loc = {1, 3, 5, 7};
  p.code.push_back(setp);
  EXPECT_TRUE(check_executable(p, "the interpreter").ok());
  for (Opcode runs : {Opcode::Dsx, Opcode::Dsy, Opcode::TexLdD}) { // 2x2 quads, rules F8-F10
    Instruction gradient;
    gradient.op = runs;
    p.code.push_back(gradient);
    EXPECT_TRUE(check_executable(p, "SPIR-V").ok());
    p.code.pop_back();
  }
  Instruction kill; // a predicated texkill runs (NUMERICS.md F3)
  kill.op = Opcode::TexKill;
  kill.pred.emplace();
  kill.loc = {1, 4, 2, 5};
  p.code.push_back(kill);
  EXPECT_TRUE(check_executable(p, "SPIR-V").ok());
  p.code.pop_back();
  Declaration fog; // fog0 runs (an extra semantic, NUMERICS.md F6); psize0 is vertex-only
  fog.reg.file = RegFile::Input;
  fog.reg.index = 2;
  fog.usage = DeclUsage::Fog;
  fog.loc = {1, 5, 1, 4};
  p.decls.push_back(fog);
  EXPECT_TRUE(check_executable(p, "the interpreter").ok());
  Declaration psize = fog;
  psize.reg.index = 3;
  psize.usage = DeclUsage::PSize;
  psize.loc = {1, 6, 1, 4};
  p.decls.push_back(psize);
  const Status s = check_executable(p, "the interpreter");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.diagnostics()[0].loc.line, 6u);
  EXPECT_NE(s.diagnostics()[0].message.find("the semantic psize0 in a pixel program"),
            std::string::npos);
}

Declaration linked(RegFile file, uint32_t index, DeclUsage usage, uint8_t usage_index,
                   uint32_t line) {
  Declaration d;
  d.reg.file = file;
  d.reg.index = index;
  d.usage = usage;
  d.usage_index = usage_index;
  d.loc = {1, line, 1, 4};
  return d;
}

Program ps30(std::vector<Declaration> decls) {
  Program p;
  p.profile = Profile::ps_3_0;
  p.decls = std::move(decls);
  return p;
}

// NUMERICS.md F6: semantics the 2.0 interface has no register for take the texcoord slots the
// program leaves free, t7 down, in (usage, index) order whatever the register numbers.
TEST(LaterProfiles, ExtraSemanticsTakeTheFreeTexcoordSlotsFromTheTop) {
  const Program p = ps30({linked(RegFile::Input, 0, DeclUsage::Tangent, 0, 2),
                          linked(RegFile::Input, 1, DeclUsage::TexCoord, 7, 3),
                          linked(RegFile::Input, 2, DeclUsage::Normal, 0, 4),
                          linked(RegFile::Input, 3, DeclUsage::Normal, 1, 5)});
  ASSERT_TRUE(check_executable(p, "SPIR-V").ok());
  const Program l = link_by_semantic(p);
  // normal0 < normal1 < tangent0 (usage codes 3, 3, 6); texcoord7 keeps t7.
  EXPECT_EQ(l.decls[0].reg.file, RegFile::Texture);
  EXPECT_EQ(l.decls[0].reg.index, 4u); // tangent0
  EXPECT_EQ(l.decls[1].reg.index, 7u); // texcoord7
  EXPECT_EQ(l.decls[2].reg.index, 6u); // normal0
  EXPECT_EQ(l.decls[3].reg.index, 5u); // normal1
}

TEST(LaterProfiles, ExtraSemanticsBeyondTheFreeSlotsAreRefused) {
  std::vector<Declaration> d;
  for (uint8_t t = 0; t < 7; ++t) d.push_back(linked(RegFile::Input, t, DeclUsage::TexCoord, t, 2));
  d.push_back(linked(RegFile::Input, 7, DeclUsage::Normal, 0, 3));   // takes t7
  d.push_back(linked(RegFile::Input, 8, DeclUsage::Binormal, 0, 4)); // nothing left
  const Status s = check_executable(ps30(d), "SPIR-V");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.diagnostics()[0].loc.line, 4u);
  EXPECT_NE(s.diagnostics()[0].message.find("the semantic binormal0"), std::string::npos);
}

// A pair links where both stages place their extra semantics alike; where they do not, the
// pair is refused rather than reading one semantic as another.
TEST(LaterProfiles, PairsWhoseExtraSemanticsLandApartAreRefused) {
  Program vs;
  vs.profile = Profile::vs_3_0;
  vs.decls = {linked(RegFile::Output, 0, DeclUsage::Position, 0, 2),
              linked(RegFile::Output, 1, DeclUsage::Normal, 0, 3),
              linked(RegFile::Output, 2, DeclUsage::Tangent, 0, 4)};
  const Program both = ps30({linked(RegFile::Input, 3, DeclUsage::Tangent, 0, 2),
                             linked(RegFile::Input, 5, DeclUsage::Normal, 0, 3)});
  EXPECT_TRUE(check_semantic_pair(vs, both).ok());
  // Tangent alone goes to t7 in the pixel program, where the vertex program puts normal0.
  const Program tangent_only = ps30({linked(RegFile::Input, 0, DeclUsage::Tangent, 0, 2)});
  const Status s = check_semantic_pair(vs, tangent_only);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("reads tangent0 from texcoord slot t7, where the vertex program "
                             "puts normal0"),
            std::string::npos)
      << s.message();
  // A vs_2_0 that writes oT7 cannot feed a ps_3_0 normal0 (which sits in t7).
  Program vs20;
  vs20.profile = Profile::vs_2_0;
  Instruction mov;
  mov.op = Opcode::Mov;
  mov.dst = DstOperand{RegFile::TexCrdOut, 7, kFullMask, {1, 2, 5, 3}};
  vs20.code.push_back(mov);
  EXPECT_FALSE(
      check_semantic_pair(vs20, ps30({linked(RegFile::Input, 0, DeclUsage::Normal, 0, 2)})).ok());
  vs20.code[0].dst->index = 6;
  EXPECT_TRUE(
      check_semantic_pair(vs20, ps30({linked(RegFile::Input, 0, DeclUsage::Normal, 0, 2)})).ok());
}

// NUMERICS.md F6: fog0 rides in a free texcoord slot in both 3.0 stages (t6 here: t7 is
// texcoord7's), and a vs_2_0's scalar oFog is moved into that slot, saturated.
TEST(LaterProfiles, Fog0IsAnExtraSemanticAndAVs20FeedsItsOFog) {
  const Program ps = ps30({linked(RegFile::Input, 2, DeclUsage::Fog, 0, 2),
                           linked(RegFile::Input, 5, DeclUsage::TexCoord, 7, 3)});
  ASSERT_TRUE(check_executable(ps, "SPIR-V").ok());
  ASSERT_EQ(fog_slot(ps), std::optional<uint32_t>(6));
  const Program l = link_by_semantic(ps);
  EXPECT_EQ(l.decls[0].reg.file, RegFile::Texture);
  EXPECT_EQ(l.decls[0].reg.index, 6u);
  Program vs30;
  vs30.profile = Profile::vs_3_0;
  vs30.decls = {linked(RegFile::Output, 0, DeclUsage::Position, 0, 2),
                linked(RegFile::Output, 4, DeclUsage::Fog, 0, 3),
                linked(RegFile::Output, 1, DeclUsage::TexCoord, 7, 4)};
  EXPECT_TRUE(check_semantic_pair(vs30, ps).ok());
  const Program lv = link_by_semantic(vs30);
  EXPECT_EQ(lv.decls[1].reg.file, RegFile::TexCrdOut);
  EXPECT_EQ(lv.decls[1].reg.index, 6u);
  EXPECT_EQ(feed_fog(vs30, ps).decls[1].reg.file, RegFile::Output); // 3.0: unchanged
  Program vs20;
  vs20.profile = Profile::vs_2_0;
  Instruction mov;
  mov.op = Opcode::Mov;
  mov.dst = DstOperand{RegFile::RastOut, kRastFog, 0x1, {1, 2, 5, 4}};
  vs20.code.push_back(mov);
  EXPECT_TRUE(check_semantic_pair(vs20, ps).ok());
  const Program fed = feed_fog(vs20, ps);
  EXPECT_EQ(fed.code[0].dst->file, RegFile::TexCrdOut);
  EXPECT_EQ(fed.code[0].dst->index, 6u);
  EXPECT_EQ(fed.code[0].dst->mask, 0x1);
  EXPECT_TRUE(fed.code[0].mods.sat);
  // Without fog0 in the pixel program, oFog stays.
  const Program no_fog = ps30({linked(RegFile::Input, 5, DeclUsage::TexCoord, 7, 3)});
  EXPECT_FALSE(fog_slot(no_fog).has_value());
  EXPECT_EQ(feed_fog(vs20, no_fog).code[0].dst->file, RegFile::RastOut);
}

// vs_3_0 may address v# and o# with aL: relative v# reads run (through the table of declared
// inputs, NUMERICS.md F13), relative o# writes are refused at the operand.
TEST(LaterProfiles, RelativeOutputsRunInVs30OnlyAndAreRefusedAtTheOperandElsewhere) {
  Program p;
  p.profile = Profile::vs_3_0;
  Instruction mov;
  mov.op = Opcode::Mov;
  mov.dst = DstOperand{RegFile::Temp, 0, kFullMask, {1, 2, 5, 2}};
  SrcOperand v;
  v.file = RegFile::Input;
  v.index = 1;
  v.rel = RelAddr{RegFile::Loop, 0, {1, 2, 9, 2}};
  v.loc = {1, 2, 9, 7};
  mov.src.push_back(v);
  p.code.push_back(mov);
  EXPECT_TRUE(check_executable(p, "SPIR-V").ok()); // v[aL + 1] runs
  p.code[0].src[0].file = RegFile::Const;          // c[aL + 1] runs
  EXPECT_TRUE(check_executable(p, "SPIR-V").ok());
  p.code[0].dst = DstOperand{RegFile::Output, 1, kFullMask, {1, 2, 5, 2}};
  p.code[0].dst->rel = RelAddr{RegFile::Loop, 0, {1, 2, 7, 2}};
  EXPECT_TRUE(check_executable(p, "SPIR-V").ok()); // o[aL + 1] runs (NUMERICS.md F13)
  // No profile writes another register relatively: r[aL] built without the assembler.
  p.code[0].dst->file = RegFile::Temp;
  Status s = check_executable(p, "SPIR-V");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.diagnostics()[0].loc.col, 5u);
  EXPECT_NE(s.diagnostics()[0].message.find("r1 addressed relatively (only a vs_3_0's o# is "
                                            "written relatively)"),
            std::string::npos)
      << s.diagnostics()[0].message;
}

// Direct3D 9 predicates arithmetic and texture instructions only: a predicated break, built
// without the assembler's validator, is refused by the IR validator every device runs first,
// at the predicate, as a Direct3D 9 rule (not as something missing).
TEST(LaterProfiles, PredicatedFlowControlIsNotDirect3D9) {
  Program p;
  p.profile = Profile::ps_3_0;
  Instruction brk;
  brk.op = Opcode::Break;
  brk.loc = {1, 4, 8, 13};
  SrcOperand pred;
  pred.file = RegFile::Predicate;
  pred.loc = {1, 4, 2, 5};
  brk.pred = pred;
  p.code.push_back(brk);
  const Status s = validate_ir(p);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.diagnostics()[0].loc.col, 2u);
  EXPECT_NE(s.diagnostics()[0].message.find(
                "break cannot be predicated: Direct3D 9 predicates arithmetic and texture "
                "instructions only"),
            std::string::npos)
      << s.diagnostics()[0].message;
  p.code[0].pred.reset(); // break outside a loop is the assembler's to refuse, not this one's
  EXPECT_TRUE(validate_ir(p).ok());
}

// relative_input_links: a ps_3_0's v# by number → the registers their semantics link to; a
// vs_3_0's v# → themselves; undeclared numbers empty; other profiles no table.
TEST(LaterProfiles, RelativeInputLinksFollowTheSemantics) {
  Program ps;
  ps.profile = Profile::ps_3_0;
  ps.decls = {linked(RegFile::Input, 0, DeclUsage::TexCoord, 0, 1),
              linked(RegFile::Input, 1, DeclUsage::Color, 0, 2),
              linked(RegFile::Input, 2, DeclUsage::TexCoord, 3, 3)};
  const RelativeLinks l = relative_input_links(ps);
  ASSERT_EQ(l.size(), 10u);
  EXPECT_EQ(l[0], (std::pair{RegFile::Texture, 0u}));
  EXPECT_EQ(l[1], (std::pair{RegFile::Input, 0u}));
  EXPECT_EQ(l[2], (std::pair{RegFile::Texture, 3u}));
  EXPECT_FALSE(l[3].has_value());
  Program vs;
  vs.profile = Profile::vs_3_0;
  vs.decls = {linked(RegFile::Input, 4, DeclUsage::Normal, 0, 1)};
  const RelativeLinks v = relative_input_links(vs);
  ASSERT_EQ(v.size(), 16u);
  EXPECT_EQ(v[4], (std::pair{RegFile::Input, 4u}));
  EXPECT_FALSE(v[0].has_value());
  vs.profile = Profile::vs_2_0;
  EXPECT_TRUE(relative_input_links(vs).empty());
}

// relative_output_links: a vs_3_0's o# by number → the 2.0 registers their semantics link
// to (texcoord2 → oT2, color0 → oD0, position0 → oPos); undeclared numbers empty; twelve
// entries; other profiles no table. link_by_semantic keeps a relative destination's o#.
TEST(LaterProfiles, RelativeOutputLinksFollowTheSemantics) {
  Program vs;
  vs.profile = Profile::vs_3_0;
  vs.decls = {linked(RegFile::Output, 0, DeclUsage::Position, 0, 1),
              linked(RegFile::Output, 3, DeclUsage::TexCoord, 2, 2),
              linked(RegFile::Output, 4, DeclUsage::TexCoord, 0, 3),
              linked(RegFile::Output, 5, DeclUsage::Color, 0, 4)};
  const RelativeLinks l = relative_output_links(vs);
  ASSERT_EQ(l.size(), 12u);
  EXPECT_EQ(l[0], (std::pair{RegFile::RastOut, kRastPos}));
  EXPECT_EQ(l[3], (std::pair{RegFile::TexCrdOut, 2u}));
  EXPECT_EQ(l[4], (std::pair{RegFile::TexCrdOut, 0u}));
  EXPECT_EQ(l[5], (std::pair{RegFile::AttrOut, 0u}));
  EXPECT_FALSE(l[1].has_value());
  EXPECT_FALSE(l[6].has_value());
  Instruction mov;
  mov.op = Opcode::Mov;
  mov.dst = DstOperand{RegFile::Output, 3, kFullMask, {}};
  mov.dst->rel = RelAddr{RegFile::Loop, 0, {}};
  vs.code.push_back(mov);
  EXPECT_TRUE(writes_outputs_relatively(vs));
  const Program linked_vs = link_by_semantic(vs);
  EXPECT_EQ(linked_vs.code[0].dst->file, RegFile::Output);
  EXPECT_EQ(linked_vs.code[0].dst->index, 3u);
  vs.profile = Profile::vs_2_0;
  EXPECT_TRUE(relative_output_links(vs).empty());
}

// texldl runs in both stages: ps_3_0's reads the pixel samplers, vs_3_0's (vertex texture
// fetch) the pass's vertex samplers (NUMERICS.md F14).
TEST(LaterProfiles, TexldlRunsInBothStages) {
  Program p;
  p.profile = Profile::ps_3_0;
  Instruction texldl;
  texldl.op = Opcode::TexLdL;
  texldl.loc = {1, 3, 1, 6};
  p.code.push_back(texldl);
  EXPECT_TRUE(check_executable(p, "SPIR-V").ok());
  p.profile = Profile::vs_3_0;
  EXPECT_TRUE(check_executable(p, "the interpreter").ok());
  EXPECT_TRUE(check_executable(p, "SPIR-V").ok());
}

// vs_3_0's s0..s3 are its vertex samplers (texldl reads them): validate_ir lets the VM and the
// code generator address those four and no more; vs_2_0 has none.
TEST(LaterProfiles, Vs30AddressesFourSamplers) {
  Program p;
  p.profile = Profile::vs_3_0;
  Instruction texldl;
  texldl.op = Opcode::TexLdL;
  texldl.loc = {1, 5, 1, 6};
  texldl.dst = DstOperand{RegFile::Temp, 0, kFullMask, {}};
  SrcOperand coord, sampler;
  coord.file = RegFile::Const;
  sampler.file = RegFile::Sampler;
  sampler.index = 3;
  texldl.src = {coord, sampler};
  p.code.push_back(texldl);
  EXPECT_TRUE(validate_ir(p).ok());
  p.code[0].src[1].index = 4;
  Status s = validate_ir(p);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("s4 is outside the 4 registers vs_3_0 can address"), std::string::npos)
      << s.message();
  p.profile = Profile::vs_2_0;
  p.code[0].src[1].index = 0;
  EXPECT_FALSE(validate_ir(p).ok());
}
