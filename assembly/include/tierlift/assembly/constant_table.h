// The constant table fxc and D3DX write into a token stream as a comment ("CTAB"): the name,
// register set, first register and register count of every constant the shader reads, so
// that tools can show `c4..c7 g_mWorldViewProj` and a user can set a constant by its name.
//
// Layout (the D3DXSHADER_CONSTANTTABLE of the D3DX headers, all offsets in bytes from the
// first byte after the "CTAB" four-character code, little-endian):
//   header  Size(=28) Creator(ofs) Version Constants(count) ConstantInfo(ofs) Flags Target(ofs)
//   info    Name(ofs) RegisterSet:16 RegisterIndex:16 RegisterCount:16 Reserved:16
//           TypeInfo(ofs) DefaultValue(ofs)                              (20 bytes each)
//   type    Class:16 Type:16 Rows:16 Columns:16 Elements:16 StructMembers:16 MemberInfo(ofs)
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/registers.h"

namespace tierlift::assembly {

enum class ConstantSet : uint16_t { Bool = 0, Int4 = 1, Float4 = 2, Sampler = 3 };

struct NamedConstant {
  std::string name;
  ConstantSet set = ConstantSet::Float4;
  uint32_t index = 0; // first register
  uint32_t count = 1; // registers it spans (a float4x4 takes 4)
  std::string type;   // "float4x4", "float3", "sampler2D", "" when the type info is absent
  // The register file the set maps to (c#, i#, b#, s#).
  ir::RegFile file() const;
  // "c4..c7" or "c4".
  std::string registers() const;
};

struct ConstantTable {
  std::string creator; // "Microsoft (R) HLSL Shader Compiler 9.29.952.3111"
  std::string target;  // "ps_2_0"
  std::vector<NamedConstant> constants;
  const NamedConstant* find(std::string_view name) const;
};

// The first CTAB comment of the stream (the version token is tokens[0]; comments follow
// it). nullopt when there is none. A CTAB whose offsets point outside the comment is a
// warning at the comment's byte offset (rule "constant-table") and is ignored: the shader
// itself is still good.
std::optional<ConstantTable> read_constant_table(const std::vector<uint32_t>& tokens,
                                                 ir::DiagnosticSink& diags, uint32_t file = 0);

// The table as comment lines that head a disassembly (the assembler skips them):
//   // CTAB: ps_2_0, Microsoft (R) HLSL Shader Compiler 9.29.952.3111
//   //   c0..c3   g_mWorldViewProj  float4x4
std::string print_constant_table(const ConstantTable& table);

} // namespace tierlift::assembly
