// One generated listing per opcode-table row and per profile where the row is legal: it
// parses, compiles and the module passes spirv-val. Flow-control rows are exercised inside
// the structure they belong to (if/else/endif, loop/endloop, call/label/ret, ...).
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "compile_valid.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/ir/opcodes.h"

using namespace tierlift;
using ir::Opcode;
using ir::OperandKind;
using ir::Profile;

namespace {

std::string flow_body(Opcode op) {
  switch (op) {
  case Opcode::If:
  case Opcode::Else:
  case Opcode::EndIf: return "if b0\nmov r4, c1\nelse\nmov r4, c2\nendif\n";
  case Opcode::Loop:
  case Opcode::EndLoop: return "mov r4, c0\nloop aL, i0\nadd r4, r4, c[aL + 1]\nendloop\n";
  case Opcode::Rep:
  case Opcode::EndRep: return "mov r4, c0\nrep i0\nadd r4, r4, c1\nendrep\n";
  case Opcode::Call:
  case Opcode::Ret:
  case Opcode::Label: return "call l0\nmov oPos, r4\nret\nlabel l0\nmov r4, v0\nret\n";
  case Opcode::CallNz:
    return "mov r4, v0\ncallnz l1, !b0\nmov oPos, r4\nret\nlabel l1\nmov r4, c1\nret\n";
  default: return {};
  }
}

// ", src, ..." for the row's sources: vectors r0, r1, r2 in turn (a scalar is its .x), the
// matrix c4, constants c5 (second source) or c6. Temp sources are r2, r3 in turn with
// `temps_apart` (the vertex listings) and take the next vector otherwise.
std::string sources(const ir::OpInfo& info, bool temps_apart) {
  const char* vec[] = {"r0", "r1", "r2"};
  const char* temps[] = {"r2", "r3"};
  int v = 0, t = 0;
  std::string s;
  for (int i = 0; i < info.num_src; ++i) {
    s += ", ";
    switch (info.src[i]) {
    case OperandKind::Scalar: s += std::string(vec[v++ % 3]) + ".x"; break;
    case OperandKind::Matrix: s += "c4"; break;
    case OperandKind::Const: s += i == 1 ? "c5" : "c6"; break;
    case OperandKind::Temp: s += temps_apart ? temps[t++ % 2] : vec[v++ % 3]; break;
    default: s += vec[v++ % 3]; break;
    }
  }
  return s;
}

// Vertex profiles: every row writes r4 from r0..r3, then oPos and oT0 read r4.
std::string vertex_listing(const ir::OpInfo& info, Profile p) {
  std::string s(ir::profile_name(p));
  s += "\ndcl_position v0\ndcl_texcoord v1\n";
  s += "def c0, 0.5, 0.25, 1.0, 2.0\n";
  if (p == Profile::vs_2_0) s += "defi i0, 3, 0, 1, 0\ndefb b0, true\n";
  s += "mov r0, v0\nmov r1, v1\nmov r2, c2\nmov r3, c3\n";
  if (info.cls == ir::OpClass::Flow) {
    const std::string body = flow_body(info.op);
    if (body.find("ret\nlabel") != std::string::npos) return s + body;
    return s + body + "mov oPos, r4\nmov oT0, r4\n";
  }
  std::string mask;
  switch (info.op) {
  case Opcode::M3x2:
  case Opcode::SinCos: mask = ".xy"; break;
  case Opcode::M3x3:
  case Opcode::M4x3:
  case Opcode::Crs: mask = ".xyz"; break;
  case Opcode::Frc: mask = p == Profile::vs_1_1 ? ".xy" : ""; break;
  case Opcode::Rcp:
  case Opcode::Rsq:
  case Opcode::Exp:
  case Opcode::Log:
  case Opcode::Expp:
  case Opcode::Logp:
  case Opcode::Pow: mask = ".x"; break;
  default: break;
  }
  std::string ins(info.mnemonic);
  if (info.op == Opcode::Mova) {
    s += "mova a0.x, r0.x\nmov r4, c[a0.x + 1]\n";
  } else if (info.op == Opcode::Nop) {
    s += "nop\nmov r4, r0\n";
  } else {
    s += "mov r4, c0\n" + ins + " r4" + mask + sources(info, true) + "\n";
  }
  return s + "mov oPos, r4\nmov oT0, r4\n";
}

std::string ps20_listing(const ir::OpInfo& info) {
  std::string s = "ps_2_0\ndcl t0\ndcl t1\ndcl v0\ndcl_2d s0\ndcl_cube s1\n";
  s += "def c0, 0.5, 0.25, 1.0, 2.0\n";
  s += "mov r0, t0\nmov r1, t1\nmov r2, v0\nmov r3, c1\n";
  std::string ins(info.mnemonic);
  switch (info.op) {
  case Opcode::TexLd:
  case Opcode::TexLdP:
  case Opcode::TexLdB: s += ins + " r4, t0, s0\n" + ins + " r5, r1, s1\nadd r4, r4, r5\n"; break;
  case Opcode::TexKill: s += "texkill r0\ntexkill t1\nmov r4, r2\n"; break;
  case Opcode::Nop: s += "nop\nmov r4, r0\n"; break;
  default: {
    std::string mask;
    if (info.op == Opcode::M3x2 || info.op == Opcode::SinCos) mask = ".xy";
    if (info.op == Opcode::M3x3 || info.op == Opcode::M4x3 || info.op == Opcode::Crs) mask = ".xyz";
    s += "mov r4, c0\n" + ins + " r4" + mask + sources(info, false) + "\n";
  }
  }
  return s + "mov oC0, r4\n";
}

std::string ps14_listing(const ir::OpInfo& info) {
  std::string s = "ps_1_4\ndef c0, 0.5, 0.25, 1.0, 0.75\n";
  switch (info.op) {
  case Opcode::TexLd14:
    return s + "texld r0, t0\ntexld r1, t1_dw.xyw\nphase\ntexld r2, r0_dz\nadd r0, r0, r2\n";
  case Opcode::TexCrd: return s + "texcrd r0.rgb, t0\ntexcrd r1.rg, t1_dw.xyw\nadd r0, r0, r1\n";
  case Opcode::TexKill: return s + "texkill t0\ntexld r0, t1\nphase\ntexkill r0\nmov r0, v0\n";
  case Opcode::TexDepth: return s + "texcrd r5.rgb, t0\nphase\ntexdepth r5\nmov r0, v0\n";
  case Opcode::Phase: return s + "texld r1, t0\nphase\ntexld r2, r1\nmov r0, r2\n";
  case Opcode::Bem:
    return s +
           "texld r0, t0\ntexcrd r1.rgb, t1\nbem r2.rg, r0, r1\nphase\ntexld r3, r2\nmov r0, r3\n";
  case Opcode::Nop: return s + "texld r0, t0\nnop\n";
  default: break;
  }
  s += "texld r0, t0\ntexcrd r1.rgb, t1\n";
  s += std::string(info.mnemonic) + "_sat r2";
  const char* vec[] = {"r0", "r1_bx2", "1-r0"};
  for (int i = 0; i < info.num_src; ++i) s += std::string(", ") + vec[i % 3];
  return s + "\nmov_x2 r0, r2\n";
}

std::string ps11_listing(const ir::OpInfo& info, Profile p) {
  std::string s(ir::profile_name(p));
  s += "\ndef c0, 0.5, 0.25, 1.0, 0.75\n";
  const std::string mn(info.mnemonic);
  switch (info.op) {
  case Opcode::Tex:
  case Opcode::TexCoord: return s + mn + " t0\n" + mn + " t1\nadd r0, t0, t1\n";
  case Opcode::TexKill: return s + "texkill t0\ntex t1\nmov r0, t1\n";
  case Opcode::TexBem:
  case Opcode::TexBemL:
  case Opcode::TexReg2Ar:
  case Opcode::TexReg2Gb:
  case Opcode::TexReg2Rgb:
  case Opcode::TexDp3:
  case Opcode::TexDp3Tex: return s + "tex t0\n" + mn + " t1, t0\nmul r0, t1, v0\n";
  case Opcode::TexM3x2Pad:
  case Opcode::TexM3x2Tex:
    return s + "tex t0\ntexm3x2pad t1, t0_bx2\ntexm3x2tex t2, t0_bx2\nmov r0, t2\n";
  case Opcode::TexM3x2Depth:
    return s + "tex t0\ntexm3x2pad t1, t0\ntexm3x2depth t2, t0\nmov r0, v0\n";
  case Opcode::TexM3x3Pad:
  case Opcode::TexM3x3Tex:
  case Opcode::TexM3x3:
  case Opcode::TexM3x3VSpec: {
    const std::string last = info.op == Opcode::TexM3x3Pad ? "texm3x3tex" : mn;
    return s + "tex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\n" + last + " t3, t0\nmov r0, t3\n";
  }
  case Opcode::TexM3x3Spec:
    return s + "tex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3spec t3, t0, c0\nmov r0, t3\n";
  case Opcode::Nop: return s + "tex t0\nnop\nmov r0, t0\n";
  case Opcode::Cnd: return s + "tex t0\nmov r0, v0\ncnd r1, r0.a, t0, v1\nmov r0, r1\n";
  default: break;
  }
  s += "tex t0\ntex t1\n" + mn + "_x2 r1";
  const char* vec[] = {"t0", "v0_bias", "-t1"};
  for (int i = 0; i < info.num_src; ++i) s += std::string(", ") + vec[i % 3];
  return s + "\nmov_sat r0, r1\n";
}

std::optional<std::string> listing_for(const ir::OpInfo& info, Profile p) {
  if (info.cls == ir::OpClass::Decl) return std::nullopt; // every listing has dcl/def
  if (ir::is_vertex(p)) return vertex_listing(info, p);
  if (p == Profile::ps_2_0) return ps20_listing(info);
  if (p == Profile::ps_1_4) return ps14_listing(info);
  return ps11_listing(info, p);
}

void expect_compiles(const std::string& text) {
  SCOPED_TRACE(text);
  auto parsed = assembly::parse_text(text, "<generated>");
  ASSERT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  tierlift::test::compile_valid(*parsed.program, parsed.sources);
}

} // namespace

TEST(CodegenOpcodes, EveryRowLegalInEachProfileCompilesAndValidates) {
  int listings = 0;
  for (const ir::OpInfo& info : ir::opcode_table()) {
    // The executable profiles; 2.x and 3.0 are refused (CodegenLater tests).
    for (Profile p : ir::kExecutableProfiles) {
      if (!ir::legal_in(info, p)) continue;
      auto text = listing_for(info, p);
      if (!text) continue;
      SCOPED_TRACE(std::string(info.mnemonic) + " in " + std::string(ir::profile_name(p)));
      expect_compiles(*text);
      ++listings;
    }
  }
  EXPECT_GT(listings, 150);
}

TEST(CodegenOpcodes, CoIssuedPairCompiles) {
  expect_compiles("ps_1_1\ntex t0\nmul r0.rgb, t0, v0\n+add r0.a, t0, v1\n");
  expect_compiles("ps_1_3\ntex t0\nmov r0, v0\ndp3 r1.rgb, t0_bx2, v0_bx2\n+cnd r1.a, r0.a, t0, "
                  "v1\nmov r0, r1\n");
}

TEST(CodegenOpcodes, Vs11RelativeAddressingCompiles) {
  expect_compiles("vs_1_1\ndcl_position v0\ndef c3, 1, 2, 3, 4\nmov a0.x, v0.x\n"
                  "mov r0, c[a0.x + 2]\nm4x4 oPos, r0, c[a0.x + 4]\n");
}
