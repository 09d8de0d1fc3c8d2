// Bit layout of Direct3D 9 shader tokens (docs/d3d9-rules.md §11.1), shared by the writer and the
// reader so the two directions cannot drift apart. Every field is a mask and a shift; the
// helpers only ever shift unsigned values, so no input can reach undefined behaviour.
#pragma once

#include <cstdint>

#include "tierlift/ir/profile.h"

namespace tierlift::assembly::bc {

// Special whole tokens.
inline constexpr uint32_t kEndToken = 0x0000FFFFu;
inline constexpr uint32_t kPhaseToken = 0x0000FFFDu;
inline constexpr uint16_t kCommentOpcode = 0xFFFE;
inline constexpr uint16_t kEndOpcode = 0xFFFF;

// Instruction token.
inline constexpr uint32_t kOpcodeMask = 0x0000FFFFu; // bits 0–15
inline constexpr int kControlShift = 16;             // bits 16–23
inline constexpr uint32_t kControlMask = 0x00FF0000u;
inline constexpr int kLengthShift = 24; // bits 24–27, SM2 only
inline constexpr uint32_t kLengthMask = 0x0F000000u;
inline constexpr uint32_t kPredicatedBit = 1u << 28;
inline constexpr uint32_t kCoissueBit = 1u << 30;
// Bits an instruction token of these profiles never sets: predication (SM2.x+), bit 29
// (reserved) and bit 31 (only parameter tokens set it).
inline constexpr uint32_t kInstrReserved = kPredicatedBit | (1u << 29) | (1u << 31);

// Comment token: 0xFFFE in the low half, DWORD count in bits 16–30.
inline constexpr int kCommentSizeShift = 16;
inline constexpr uint32_t kCommentSizeMask = 0x7FFF0000u;

// Parameter tokens (destination and source).
inline constexpr uint32_t kParamBit = 1u << 31;
inline constexpr uint32_t kRegNumMask = 0x000007FFu; // bits 0–10
inline constexpr uint32_t kMaxRegNum = kRegNumMask;
inline constexpr int kTypeHiShift = 11 - 3; // type bits 3–4 → token bits 11–12
inline constexpr uint32_t kTypeHiMask = 0x00001800u;
inline constexpr int kTypeLoShift = 28; // type bits 0–2 → token bits 28–30
inline constexpr uint32_t kTypeLoMask = 0x70000000u;
inline constexpr uint32_t kRelativeBit = 1u << 13;
inline constexpr uint32_t kParamReserved = 0x0000C000u; // bits 14–15
inline constexpr int kMaskShift = 16;                   // destination bits 16–19
inline constexpr uint32_t kMaskMask = 0x000F0000u;
inline constexpr int kResultModShift = 20; // destination bits 20–23
inline constexpr uint32_t kResultModMask = 0x00F00000u;
inline constexpr uint32_t kResultSat = 1, kResultPp = 2, kResultCentroid = 4;
inline constexpr int kShiftShift = 24; // destination bits 24–27, signed 4 bits
inline constexpr uint32_t kShiftMask = 0x0F000000u;
inline constexpr int kSwizzleShift = 16; // source bits 16–23
inline constexpr uint32_t kSwizzleMask = 0x00FF0000u;
inline constexpr int kSrcModShift = 24; // source bits 24–27
inline constexpr uint32_t kSrcModMask = 0x0F000000u;

// dcl usage/type token.
inline constexpr uint32_t kUsageMask = 0x0000001Fu; // bits 0–4
inline constexpr int kUsageIndexShift = 16;         // bits 16–19
inline constexpr uint32_t kUsageIndexMask = 0x000F0000u;
inline constexpr int kSamplerTypeShift = 27; // bits 27–30
inline constexpr uint32_t kSamplerTypeMask = 0x78000000u;

// The 5-bit register type is split across two fields of the parameter token.
constexpr uint32_t encode_regtype(uint8_t type) {
  return ((uint32_t{type} << kTypeLoShift) & kTypeLoMask) |
         ((uint32_t{type} << kTypeHiShift) & kTypeHiMask);
}
constexpr uint8_t decode_regtype(uint32_t token) {
  return static_cast<uint8_t>(((token & kTypeLoMask) >> kTypeLoShift) |
                              ((token & kTypeHiMask) >> kTypeHiShift));
}

// Shift as a signed 4-bit field: +1..+3 (x2..x8) and -1..-3 (d2..d8 = 15..13).
constexpr uint32_t encode_shift(int shift) {
  return (static_cast<uint32_t>(shift) & 0xFu) << kShiftShift;
}
constexpr int decode_shift(uint32_t token) {
  int raw = static_cast<int>((token & kShiftMask) >> kShiftShift);
  return raw >= 8 ? raw - 16 : raw;
}

// Shader model 1 streams carry no instruction length; operand counts come from the table.
constexpr bool has_length_field(ir::Profile p) {
  return ir::major_of(p) >= 2;
}

} // namespace tierlift::assembly::bc
