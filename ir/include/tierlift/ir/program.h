// The IR: one Program per listing, whatever profile or spelling it came from.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/profile.h"
#include "tierlift/ir/registers.h"
#include "tierlift/ir/source.h"

namespace tierlift::ir {

// Source modifiers, numbered as in bytecode bits 24–27 (docs/d3d9-rules.md §4.2).
enum class SrcMod : uint8_t {
  None = 0,
  Neg = 1,
  Bias = 2,
  BiasNeg = 3,
  Bx2 = 4,
  Bx2Neg = 5,
  Comp = 6,
  X2 = 7,
  X2Neg = 8,
  Dz = 9,
  Dw = 10,
  Abs = 11,
  AbsNeg = 12,
  Not = 13
};

// Relative addressing: c[a0.x + n], c[aL + n]. The constant offset lives in the operand's
// index; this names the register that is added to it.
struct RelAddr {
  RegFile file = RegFile::Addr; // Addr (a0) or Loop (aL)
  uint8_t component = 0;        // 0..3 = x..w, the one component added (aL: 0)
  SourceLoc loc;
  // The swizzle field of the vs_2_0 address token, when the text or the stream gave one:
  // Microsoft's assembler keeps "a0.xyww" as written (0xF4) and writes the identity for a
  // bare "a0" and for aL (Wine's d3dcompiler asm tests). The component added is the first
  // one selected. Unset: the replicate of `component` for a0, the identity for aL.
  // (Initialised, so that RelAddr{file, component, loc} stays free of
  // -Wmissing-field-initializers.)
  std::optional<uint8_t> swizzle = std::nullopt;
  uint8_t token_swizzle() const {
    if (swizzle) return *swizzle;
    return file == RegFile::Loop ? kIdentitySwizzle : replicate_swizzle(component & 3);
  }
};

struct SrcOperand {
  RegFile file = RegFile::Temp;
  uint32_t index = 0;
  std::optional<RelAddr> rel;
  uint8_t swizzle = kIdentitySwizzle;
  SrcMod mod = SrcMod::None;
  SourceLoc loc;
};

struct DstOperand {
  RegFile file = RegFile::Temp;
  uint32_t index = 0;
  uint8_t mask = kFullMask;
  SourceLoc loc;
  // o[a0.x + n] / o[aL + n]: vs_3_0 outputs addressed relatively.
  std::optional<RelAddr> rel = std::nullopt;
};

// Instruction (result) modifiers. shift: +1 _x2, +2 _x4, +3 _x8, -1 _d2, -2 _d4, -3 _d8.
struct InstrMods {
  bool sat = false;
  bool pp = false;
  bool centroid = false;
  int8_t shift = 0;
};

struct Instruction {
  Opcode op = Opcode::Nop;
  InstrMods mods;
  bool coissue = false; // "+" prefix (ps_1_x)
  // "(p0.x)" / "(!p0)" before the mnemonic (2.x, 3.0): p0 with its swizzle and SrcMod::Not.
  std::optional<SrcOperand> pred;
  std::optional<DstOperand> dst;
  std::vector<SrcOperand> src;
  SourceLoc loc;    // the mnemonic
  uint32_t seq = 0; // position among all statements of the listing (decls, defs, code)
};

enum class DeclUsage : uint8_t {
  Position = 0,
  BlendWeight,
  BlendIndices,
  Normal,
  PSize,
  TexCoord,
  Tangent,
  Binormal,
  TessFactor,
  PositionT,
  Color,
  Fog,
  Depth,
  Sample
};
enum class SamplerType : uint8_t { Unknown = 0, Tex2D = 2, Cube = 3, Volume = 4 };

// dcl_usage[N] v# (vertex), dcl[_pp][_centroid] v#/t#[.mask] (ps_2_0), dcl_2d/cube/volume s#.
struct Declaration {
  DstOperand reg;
  DeclUsage usage = DeclUsage::Position; // vertex inputs only
  uint8_t usage_index = 0;
  SamplerType sampler_type = SamplerType::Unknown; // samplers only
  InstrMods mods;                                  // _pp, _centroid on ps_2_0 dcl
  SourceLoc loc;
  uint32_t seq = 0;
};

// def c#, defi i#, defb b#. Values are kept as raw 32-bit patterns so that NaN, -0 and
// denormals survive printing, bytecode and comparison unchanged.
struct ConstDef {
  RegFile file = RegFile::Const; // Const, ConstInt or ConstBool
  uint32_t index = 0;
  std::array<uint32_t, 4> raw{}; // ConstBool uses raw[0] (0 or 1)
  SourceLoc loc;
  uint32_t seq = 0;
  float f(int i) const { return std::bit_cast<float>(raw[i]); }
  int32_t i(int k) const { return static_cast<int32_t>(raw[k]); }
  bool b() const { return raw[0] != 0; }
};

// A comment token of the stream (D3DSIO_COMMENT: the "CTAB" constant table, fxc's debug
// information, or any other block a tool put there), kept word for word so that assembling
// a disassembled stream gives back the same bytes. It means nothing to the shader: same_ir
// leaves comment blocks out, and only the printer, the assembler and the disassembler read
// them. Text form: docs/d3d9-rules.md, "Comment blocks".
struct CommentBlock {
  std::vector<uint32_t> words; // the payload, without the comment token itself
  SourceLoc loc;
  uint32_t seq = 0;
};

struct Program {
  Profile profile = Profile::vs_1_1;
  SourceLoc version_loc;
  std::vector<Declaration> decls;
  std::vector<ConstDef> defs;
  std::vector<Instruction> code; // executable instructions, in order (incl. phase, labels)
  std::vector<CommentBlock> comments;

  ShaderStage stage() const { return stage_of(profile); }
  // Statements in listing order (decls, defs, code and comment blocks interleaved by seq).
  struct Statement {
    enum class Kind { Decl, Def, Code, Comment } kind;
    size_t index;
  };
  std::vector<Statement> statements() const;
};

// Structural equality, ignoring source positions and comment blocks. Used by the
// round-trip tests.
bool same_ir(const Program& a, const Program& b);
// First difference as a readable line, or "" when same_ir holds.
std::string ir_difference(const Program& a, const Program& b);

} // namespace tierlift::ir
