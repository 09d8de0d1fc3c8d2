#include "tierlift/ir/registers.h"

#include <fmt/format.h>

namespace tierlift::ir {

uint8_t bytecode_regtype(RegFile f) {
  switch (f) {
  case RegFile::Temp: return 0;
  case RegFile::Input: return 1;
  case RegFile::Const: return 2;
  case RegFile::Addr: return 3;
  case RegFile::Texture: return 3;
  case RegFile::RastOut: return 4;
  case RegFile::AttrOut: return 5;
  case RegFile::TexCrdOut: return 6;
  case RegFile::ConstInt: return 7;
  case RegFile::ColorOut: return 8;
  case RegFile::DepthOut: return 9;
  case RegFile::Sampler: return 10;
  case RegFile::ConstBool: return 14;
  case RegFile::Loop: return 15;
  case RegFile::Label: return 18;
  case RegFile::Output: return 6;
  case RegFile::Predicate: return 19;
  case RegFile::Misc: return 17;
  }
  return 0;
}

std::optional<RegFile> regfile_from_bytecode(uint8_t type, Profile profile) {
  const ShaderStage stage = stage_of(profile);
  switch (type) {
  case 0: return RegFile::Temp;
  case 1: return RegFile::Input;
  case 2: return RegFile::Const;
  case 3: return stage == ShaderStage::Vertex ? RegFile::Addr : RegFile::Texture;
  case 4: return RegFile::RastOut;
  case 5: return RegFile::AttrOut;
  case 6: return profile == Profile::vs_3_0 ? RegFile::Output : RegFile::TexCrdOut;
  case 7: return RegFile::ConstInt;
  case 8: return RegFile::ColorOut;
  case 9: return RegFile::DepthOut;
  case 10: return RegFile::Sampler;
  case 14: return RegFile::ConstBool;
  case 15: return RegFile::Loop;
  case 17: return RegFile::Misc;
  case 18: return RegFile::Label;
  case 19: return RegFile::Predicate;
  default: return std::nullopt;
  }
}

std::string register_name(RegFile f, uint32_t index) {
  switch (f) {
  case RegFile::Temp: return fmt::format("r{}", index);
  case RegFile::Input: return fmt::format("v{}", index);
  case RegFile::Const: return fmt::format("c{}", index);
  case RegFile::Addr: return "a0";
  case RegFile::Texture: return fmt::format("t{}", index);
  case RegFile::RastOut: return index == kRastPos ? "oPos" : index == kRastFog ? "oFog" : "oPts";
  case RegFile::AttrOut: return fmt::format("oD{}", index);
  case RegFile::TexCrdOut: return fmt::format("oT{}", index);
  case RegFile::ConstInt: return fmt::format("i{}", index);
  case RegFile::ColorOut: return fmt::format("oC{}", index);
  case RegFile::DepthOut: return "oDepth";
  case RegFile::Sampler: return fmt::format("s{}", index);
  case RegFile::ConstBool: return fmt::format("b{}", index);
  case RegFile::Loop: return "aL";
  case RegFile::Label: return fmt::format("l{}", index);
  case RegFile::Output: return fmt::format("o{}", index);
  case RegFile::Predicate: return fmt::format("p{}", index);
  case RegFile::Misc: return index == kMiscPosition ? "vPos" : "vFace";
  }
  return "?";
}

std::string swizzle_text(uint8_t swz) {
  if (swz == kIdentitySwizzle) return "";
  static constexpr char names[] = "xyzw";
  int n = 4;
  // Drop trailing repeats: the assembler repeats the last component given.
  while (n > 1 && swizzle_component(swz, n - 1) == swizzle_component(swz, n - 2)) --n;
  std::string s = ".";
  for (int i = 0; i < n; ++i) s += names[swizzle_component(swz, i)];
  return s;
}

std::string mask_text(uint8_t mask) {
  if (mask == kFullMask) return "";
  std::string s = ".";
  static constexpr char names[] = "xyzw";
  for (int i = 0; i < 4; ++i)
    if (mask & (1 << i)) s += names[i];
  return s;
}

} // namespace tierlift::ir
