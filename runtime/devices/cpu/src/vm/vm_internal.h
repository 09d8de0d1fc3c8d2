// Private types of the shader VM: the prepared program (one Step per instruction with its
// operands decoded once) and the per-invocation state that lives on the caller's stack.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "tierlift/cpu/shader_vm.h"
#include "tierlift/ir/conventions.h"
#include "tierlift/ir/numerics.h"
#include "tierlift/ir/program.h"

namespace tierlift::cpu::vm {

// One flat register array per invocation; every readable/writable file but c#, i#, b#
// and a0 lives at a fixed base, so an operand is one precomputed slot number.
inline constexpr int kTempBase = 0, kTempCount = 32;
inline constexpr int kInputBase = 32, kInputCount = 16;
inline constexpr int kTexBase = 48, kTexCount = 8;
inline constexpr int kOutBase = 56, kOutCount = 16;
// ps_3_0 vPos and vFace (RegFile::Misc), filled from the pixel's PixelInput.
inline constexpr int kMiscBase = kOutBase + kOutCount, kMiscCount = 2;
inline constexpr int kSlotCount = kMiscBase + kMiscCount;
// Output slots (relative to kOutBase). Vertex: oPos, oFog, oPts, oD0-1, oT0-7.
// Pixel: oC0-3, oDepth.
inline constexpr int kOutPos = 0, kOutFog = 1, kOutPts = 2, kOutD0 = 3, kOutT0 = 5;
inline constexpr int kOutC0 = 0, kOutDepth = 4;

inline constexpr int kMaxLoopDepth = 16;
inline constexpr int kMaxCallDepth = 32;
// A program cannot hang: loop and rep iterations per invocation are budgeted by
// ir::flow::kIterationBudget (ir/flow_rules.h), the rule the generated SPIR-V follows too.

struct Invocation;
struct Step;

using ExecFn = void (*)(const Step&, Invocation&);
// Arithmetic: compute a 4-vector result from fetched sources (s[0..3]; matrix rows follow
// src0 in s[1..4]). Never writes registers: the store is separate (co-issue, macros).
using ComputeFn = void (*)(const Step&, const Vec4* s, Vec4& out, Invocation&);

// InputRel: v[aL + n] of a vs_3_0/ps_3_0, through Prepared::rel_inputs.
enum class SrcKind : uint8_t { Slot, Const, ConstRel, InputRel, Zero };

struct SrcDesc {
  SrcKind kind = SrcKind::Zero;
  uint16_t slot = 0; // flat slot (Slot), constant index (Const/ConstRel base), v# (InputRel)
  int8_t rel = -1;   // ConstRel, InputRel: 0..3 = a0.x..w, 4 = aL
  uint8_t swz[4] = {0, 1, 2, 3};
  bool identity = true;
  ir::SrcMod mod = ir::SrcMod::None;
  bool clamp_const = false;  // ps_1_x: c# reads clamp to [-1, 1]
  const Vec4* def = nullptr; // Const: value from the listing's def (overrides the bank)
  bool simple = false;       // plain register read: no clamp, swizzle or modifier
};

// OutputRel: o[aL + n] of a vs_3_0, through Prepared::rel_outputs.
enum class DstKind : uint8_t { None, Slot, AddrFloor, AddrRound, OutputRel };

struct DstDesc {
  DstKind kind = DstKind::None;
  uint16_t slot = 0; // flat slot (Slot), o# number (OutputRel)
  int8_t rel = -1;   // OutputRel: 0..3 = a0.x..w, 4 = aL
  uint8_t mask = 0xF;
  float scale = 1.0f; // instruction shift as a power of two (ps_1_x)
  bool sat = false;
  bool range = false; // ps_1_x: clamp to ±max_value
  float max_value = 1.0f;
  int fixed_bits = 0;   // ps_1_x fixed-point emulation (0 = off)
  bool flush = false;   // denormals flushed (NUMERICS.md rule 13, Rounding::Llvmpipe)
  uint16_t out_bit = 0; // output slots: bit in Invocation::out_written
  bool plain = false;   // register write with no shift, clamp, _sat or quantising
};

struct Step {
  ExecFn exec = nullptr;
  ComputeFn compute = nullptr;
  std::array<SrcDesc, 4> src{};
  uint8_t nsrc = 0;
  uint8_t rows = 0; // matrix macros: rows fetched after src0
  DstDesc dst;
  int32_t target = -1; // flow: jump target (pc)
  int32_t aux = 0;     // flow: i#/b# index or p0 component; texture: stage / pad row
  bool negate = false; // callnz !b#, if !p0.x
  uint8_t compare = 0; // if_comp / break_comp / setp_comp: ir::flow::Comparison
  // A predicated instruction ("(p0.x) add", "(!p0) mov"): exec is exec_predicated, which
  // narrows the write mask to the components whose predicate holds and runs `inner`.
  ExecFn inner = nullptr;
  uint8_t pred_swz[4] = {0, 1, 2, 3};
  bool pred_not = false;
  int8_t pad_row = 0;    // texm3x2pad/texm3x3pad: 0 = u', 1 = v'
  bool gradient = false; // dsx/dsy: a quad runs its lanes up to this step together (vm_quad.cpp)
  std::optional<std::array<int32_t, 4>> int_def; // defi for loop/rep
  std::optional<bool> bool_def;                  // defb for if/callnz
  const ir::Instruction* ins = nullptr;
};

// Steps point into `program` and `const_defs`: a Prepared may move (vector buffers move
// with it) but never be copied.
struct Prepared {
  Prepared() = default;
  Prepared(Prepared&&) noexcept = default;
  Prepared& operator=(Prepared&&) noexcept = default;
  Prepared(const Prepared&) = delete;
  Prepared& operator=(const Prepared&) = delete;

  ir::Program program;
  ir::Conventions conv;
  std::vector<Step> steps;
  std::vector<std::optional<Vec4>> const_defs; // by c# index (for relative reads)
  int32_t const_limit = 0;                     // relative reads outside [0, limit) → 0
  bool ps1x = false;
  // NUMERICS.md rule 13: Rounding::Llvmpipe flushes denormals in and out of every operation
  // (numerics::Denormals::Flush) and loads def constants' denormals as zeros of their sign.
  bool flush = false;
  bool ps11_13 = false;
  bool ps14 = false;
  bool vs11 = false;
  // A pixel program before ps_3_0 reads v0/v1 saturated; a ps_3_0 reads them as they come
  // (ir::saturates_colors, NUMERICS.md rule 26, F6).
  bool saturate_colors = true;
  // v[aL + n] (vs_3_0, ps_3_0): the flat slot each v# number is read from once linked, -1
  // where none is declared (ir::relative_input_links).
  std::vector<int16_t> rel_inputs;
  // o[aL + n] (vs_3_0): the flat slot each o# number writes once linked, -1 where none is
  // declared (ir::relative_output_links).
  std::vector<int16_t> rel_outputs;
  uint8_t fog_component = 0, pts_component = 0; // scalar outputs written via .y etc.
};

struct LoopFrame {
  int32_t remaining;
  int32_t step;
  int32_t saved_al;
  int32_t body_pc;
  bool is_loop; // loop (aL) vs rep
};

struct Invocation {
  Vec4 reg[kSlotCount];
  int32_t a0[4] = {0, 0, 0, 0};
  int32_t al = 0;
  uint32_t out_written = 0;
  int32_t pc = 0;
  bool stop = false;
  uint32_t iterations = 0; // loop units spent (ir::flow::kIterationBudget)
  bool p0[4] = {false, false, false, false};
  int loop_depth = 0, call_depth = 0;
  LoopFrame loops[kMaxLoopDepth];
  int32_t calls[kMaxCallDepth];
  float pad[2] = {0, 0}; // texm3x2pad / texm3x3pad results (u', v')
  const Prepared* prog = nullptr;
  const ConstantBank* consts = nullptr;
  const TextureUnit* tex = nullptr;
  const PixelInput* pin = nullptr;
  PixelOutput* pout = nullptr;
  // Quads (vm_quad.cpp): this lane's place (0 top-left, 1 top-right, 2 bottom-left,
  // 3 bottom-right) and, while a gradient step runs, its source operand as read in each of the
  // four lanes. Without a quad (nullptr) every neighbour is the pixel itself.
  uint8_t lane = 0;
  bool in_quad = false; // texkill turns the lane into a helper instead of ending it
  const Vec4* quad = nullptr;
};

// vm_program.cpp
// The program's steps, or why the VM cannot run it (rule kVmRule, subject "cpu").
ir::Result<Prepared> prepare(const ir::Program& program, const ir::Conventions& conv);
void run(const Prepared& p, Invocation& inv);
// run, recording each instruction's destination after it ran (InstructionTrace).
void run_traced(const Prepared& p, Invocation& inv, InstructionTrace& trace);
// run_traced's parts: the trace sized to the program and emptied; step `at`'s record after
// it ran (both halves of a co-issued pair).
void start_trace(const Prepared& p, InstructionTrace& trace);
void record_step(const Prepared& p, const Invocation& inv, int32_t at, InstructionTrace& trace);

// vm_operands.cpp. fetch/store take a fast inline path for the common plain operands
// (the VM runs per pixel) and fall back to the general functions otherwise.
Vec4 fetch_general(const SrcDesc& s, const Invocation& inv);
void store_general(const DstDesc& d, const Vec4& value, Invocation& inv);
// What fetch_general does after the load (ps_1_x constant clamp, _dz/_dw, swizzle,
// post-modifiers) under the program's denormal mode (NUMERICS.md rule 13): one definition for
// the per-pixel and the block executor, instantiated for both modes in vm_operands.cpp.
template <ir::numerics::Denormals D> Vec4 modify_src(const SrcDesc& s, Vec4 v);
SrcDesc decode_src(const ir::SrcOperand& op, const Prepared& p);
// A destination the profile cannot write fails (rule kVmRule).
ir::Result<DstDesc> decode_dst(const ir::DstOperand& op, const ir::InstrMods& mods,
                               const Prepared& p);
int flat_slot(ir::RegFile file, uint32_t index, ir::ShaderStage stage); // -1: not a slot
Vec4 constant_value(int32_t index, const Invocation& inv);

// The one dispatch style of the VM: each instruction family (arithmetic, texture, flow)
// fills a constexpr table of handlers indexed by ir::Opcode, once per denormal mode where
// the handlers depend on it; preparation looks the handler up once per instruction.
template <class Fn> struct OpcodeTable {
  std::array<Fn, ir::kOpcodeCount> fn{};
  template <size_t N> constexpr explicit OpcodeTable(const std::pair<ir::Opcode, Fn> (&rows)[N]) {
    for (const auto& [op, f] : rows) fn[static_cast<size_t>(op)] = f;
  }
  constexpr Fn operator[](ir::Opcode op) const {
    const auto i = static_cast<size_t>(op);
    return i < fn.size() ? fn[i] : nullptr;
  }
};

// vm_quad.cpp: the four invocations of a 2x2 quad (TL, TR, BL, BR) run to the end, each by
// itself between gradient steps and all together at each one (NUMERICS.md rule F8).
// `trace`: lane `traced`'s record of every step it ran (run_traced's), when not null.
void run_quad(const Prepared& p, Invocation* const (&lanes)[4], InstructionTrace* trace = nullptr,
              int traced = 0);

// vm_arith.cpp: the per-opcode compute table and the arithmetic executors.
ComputeFn arith_compute(ir::Opcode op, bool flush_denormals);
void exec_arith(const Step& s, Invocation& inv);
void exec_arith_pair(const Step& s, Invocation& inv);

// vm_texture.cpp
ExecFn texture_exec(ir::Opcode op, bool flush_denormals);

// vm_flow.cpp: the flow-control executor of `ins` (its operands pick the form: if b# or
// if p0, callnz with b# or p0), nullptr when there is none.
ExecFn flow_exec(const ir::Instruction& ins);
// setp_comp and the wrapper of predicated instructions (vm_flow.cpp).
void exec_setp(const Step& s, Invocation& inv);
void exec_predicated(const Step& s, Invocation& inv);

// The store's per-component rule (shift, ps_1_x range clamp, _sat, fixed-point quantise), in
// that order, under denormal mode D (d.flush picks it per program); shared by store_general
// and the block executor.
template <ir::numerics::Denormals D> inline float dst_transform(const DstDesc& d, float x) {
  namespace num = ir::numerics;
  if (d.scale != 1.0f) x = num::legacy_scale<D>(x, d.scale);
  if (d.range) x = num::legacy_ps1x_range<D>(x, d.max_value);
  if (d.sat) x = num::legacy_saturate<D>(x);
  if (d.fixed_bits > 0) x = num::legacy_fixed_quantise<D>(x, d.fixed_bits, d.max_value);
  return x;
}

inline Vec4 fetch(const SrcDesc& s, const Invocation& inv) {
  return s.simple ? inv.reg[s.slot] : fetch_general(s, inv);
}
inline void store(const DstDesc& d, const Vec4& value, Invocation& inv) {
  if (d.plain && d.mask == 0xF) {
    inv.reg[d.slot] = value;
    inv.out_written |= d.out_bit;
    return;
  }
  store_general(d, value, inv);
}

} // namespace tierlift::cpu::vm
