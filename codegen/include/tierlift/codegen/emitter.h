// Internal to the code generator: the state shared by the per-opcode emit functions
// (emit_*.cpp). Not part of the public API; codegen.h is.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "tierlift/codegen/codegen.h"
#include "tierlift/codegen/spirv_builder.h"
#include "tierlift/ir/flow_rules.h"
#include "tierlift/ir/numeric_rules.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/plain_values.h"
#include "tierlift/ir/sm3_interface.h"

namespace tierlift::codegen {

// The numeric rules every emit_* file instantiates with SpirvArith.
namespace rule = ir::numerics::rule;

// Decided by the linker (pruning.cpp) before emission.
struct EmitPlan {
  // Instructions (indices into Program::code) left out as dead.
  std::vector<bool> skip;
  // Vertex stage in a pair: exactly these outputs are declared (file, index); others are
  // not. nullopt: every output the program writes.
  std::optional<std::set<std::pair<ir::RegFile, uint32_t>>> vs_outputs;
  // v[aL + n] of a vs_3_0/ps_3_0: the linked register of each v# number
  // (ir::relative_input_links of the program before linking).
  ir::RelativeLinks relative_inputs;
  // o[aL + n] of a vs_3_0: the linked register of each o# number
  // (ir::relative_output_links of the program before linking).
  ir::RelativeLinks relative_outputs;
  // Vertex stage: oD# leave it saturated (ir::saturates_vertex_colors in a pair,
  // ir::saturates_colors of the program alone).
  bool saturate_color_outputs = true;
};

// A computed result waiting to be stored (co-issued pairs read before either writes).
struct PendingStore {
  ir::DstOperand dst;
  ir::InstrMods mods;
  Id value = 0;                   // vec4
  uint8_t mask = 0xF;             // the destination mask, possibly narrowed by the opcode
  bool within_ps1x_range = false; // ir::PlainValueFacts: the ps_1_x range clamp is a no-op
  Id pred = 0;                    // predicated instruction: bvec4, component i written if true
  size_t index = 0;               // the instruction in Program::code (CodegenOptions::trace)
};

class Emitter;

// The arithmetic back end of ir/numeric_rules.h for SPIR-V: values are ids, and each
// operation emits one instruction at width n (add/sub/mul/div decorated NoContraction).
// ftz is the identity: the device flushes its own min/max results.
struct SpirvArith {
  using V = Id;
  using B = Id;
  Emitter& e;
  int n = 4;
  Id k(float x) const;
  Id add(Id a, Id c) const;
  Id sub(Id a, Id c) const;
  Id fmul(Id a, Id c) const;
  Id fmul_y_normal(Id a, Id c) const { return fmul(a, c); }
  Id div(Id a, Id c) const;
  Id neg(Id a) const;
  Id abs(Id a) const;
  Id floor(Id a) const;
  Id sqrt(Id a) const;
  Id exp2(Id a) const;
  Id log2(Id a) const;
  Id eq(Id a, Id c) const;
  Id lt(Id a, Id c) const;
  Id gt(Id a, Id c) const;
  Id ge(Id a, Id c) const;
  Id lor(Id a, Id c) const;
  Id land(Id a, Id c) const;
  Id is_nan(Id a) const;
  Id select(Id c, Id a, Id b) const;
  Id ftz(Id a) const { return a; }
};

class Emitter {
public:
  Emitter(const ir::Program& program, const CodegenOptions& options, const EmitPlan& plan,
          ir::DiagnosticSink& diags);
  std::optional<ShaderModule> run();

  // ---- shared state, used by the emit_* files ----
  const ir::Program& prog;
  const CodegenOptions& opt;
  const EmitPlan& plan;
  ir::DiagnosticSink& diags;
  const ir::FoldedDefs defs_; // the fold-defs pass: which def of a register wins
  SpirvBuilder b;
  Id glsl = 0;
  Id t_void = 0, t_bool = 0, t_bvec4 = 0, t_float = 0, t_vec2 = 0, t_vec3 = 0, t_vec4 = 0;
  Id t_int = 0, t_ivec4 = 0, t_uint = 0;
  bool failed = false;

  // ---- numerics (emit_numerics.cpp): SPIR-V primitives; the rules come from ir/numeric_rules.h.
  Id f(float v) { return b.const_float(v); }
  Id vec4_const(float x, float y, float z, float w);
  Id splat(Id scalar);                // float → vec4
  Id bsplat(Id cond);                 // bool → bvec4
  Id comp(Id vec4, uint32_t i);       // extract component
  Id compose(Id x, Id y, Id z, Id w); // 4 floats → vec4
  Id type_of_width(int n) const { return n == 1 ? t_float : t_vec4; }
  Id bool_type(int n) const { return n == 1 ? t_bool : t_bvec4; }
  // Arithmetic with NoContraction (one rounding each, as the interpreter).
  Id fadd(Id a, Id c, int n = 4);
  Id fsub(Id a, Id c, int n = 4);
  Id fmul(Id a, Id c, int n = 4);
  Id fdiv(Id a, Id c, int n = 4);
  Id fneg(Id a, int n = 4);
  Id cmp(spv::Op op, Id a, Id c, int n = 4); // ordered compare
  Id select(Id cond, Id a, Id c, int n = 4);
  Id glsl1(uint32_t inst, Id a, int n = 4); // GLSL.std.450 unary
  // The SPIR-V back end of the numeric rules (ir/numeric_rules.h) at width n (1: float,
  // 4: vec4); every rule is instantiated with it, never rewritten here.
  SpirvArith arith(int n = 4);
  Id dot(Id a, Id c, int count); // rule::dot over the first count components of two vec4
  Id to_index(Id x);             // rule::index_range, then float → int
  // Per value, the components known never to compare equal to zero (bit c; a float: bit 0):
  // CodegenOptions::known_*_constants, carried through swizzles, negation and component
  // extraction. The rules' compares with zero fold to false there (SpirvArith::eq, lor,
  // select).
  std::unordered_map<Id, uint8_t> never_zero_;
  uint8_t never_zero(Id v) const {
    const auto it = never_zero_.find(v);
    return it == never_zero_.end() ? 0 : it->second;
  }
  void set_never_zero(Id v, uint8_t components) {
    if (components) never_zero_[v] = components;
  }
  Id false_const(int n); // false of width n
  // What ir::plain_values knows of each instruction (empty unless
  // CodegenOptions::known_ps_constants is set), and the instruction being emitted.
  ir::PlainValueFacts plain_;
  size_t current_ = 0;
  // Whether source operands a and b of the current instruction are both plain in `mask`.
  bool plain_factors(size_t a, size_t b, uint8_t mask) const;

  // ---- registers and operands (emit_operands.cpp) ----
  Id register_var(ir::RegFile file, uint32_t index); // Private vec4 (a0: ivec4)
  Id input_var(ir::RegFile file, uint32_t index);    // Input vec4 at its location
  Id load_register(ir::RegFile file, uint32_t index, const std::optional<ir::RelAddr>& rel);
  Id load_relative_input(uint32_t index, const ir::RelAddr& rel); // v[aL + n], NUMERICS.md F13
  Id relative_offset(const ir::RelAddr& rel);                     // aL or a0.c as an int
  Id load_src(const ir::SrcOperand& s, uint32_t index_offset = 0);
  Id scalar_src(const ir::SrcOperand& s); // replicate-swizzle component (the w slot)
  bool const_within_unit(const ir::SrcOperand& s) const;
  Id load_const(uint32_t index, const std::optional<ir::RelAddr>& rel);
  Id load_int_const(uint32_t index);          // ivec4
  Id load_bool_const(uint32_t index);         // bool
  Id loop_var();                              // aL: Private int
  uint32_t relative_limit() const;            // c[a0 + n] outside [0, limit) reads 0
  Id bumpenv(uint32_t stage, uint32_t which); // ps_1_x: 0 matrix, 1 luminance (vec4)
  Id aL_var_ = 0;
  void store(const PendingStore& st, bool ps1x_range);
  // The masked, predicated write of v into one register variable; where `hit` (a bool) is
  // given, the register keeps its old value unless it holds (o[aL + n], NUMERICS.md F13).
  void write_register(Id var, Id v, const PendingStore& st, Id hit = 0);
  Id ps1x_max_value() const { return spec_max_value_; }

  // ---- instruction emitters (emit_arith.cpp, emit_texture.cpp, emit_flow.cpp) ----
  // Arithmetic: the vec4 result and the mask it may write (narrowed for macros).
  bool emit_arith(const ir::Instruction& ins, PendingStore& out);
  // emit_arith's three groups, each 0 for an opcode not its own: per component (mov … cmp),
  // scalar (rcp, rsq, exp, log, pow, sincos), across components (dp*, lit, dst, matrices,
  // crs, nrm, bem).
  Id arith_per_component(const ir::Instruction& ins, uint8_t mask);
  Id arith_scalar(const ir::Instruction& ins);
  Id arith_across_components(const ir::Instruction& ins);
  bool emit_texture(const ir::Instruction& ins, std::optional<PendingStore>& out);
  // emit_texture's parts: the texm3x2 / texm3x3 family, texbem(l)'s read, the stores.
  bool emit_texture_matrix(const ir::Instruction& ins, std::optional<PendingStore>& out);
  Id bump_sample(const ir::Instruction& ins);
  Id stage_texcoord(uint32_t stage); // t# of a stage, divided by w when the stage projects
  Id dot3_texcoord(const ir::Instruction& ins, uint32_t stage); // t#·src0 over .xyz
  PendingStore texture_store(const ir::Instruction& ins, Id v);
  PendingStore depth_store(Id z); // oDepth.x = z
  bool emit_flow(const ir::Instruction& ins, size_t index);
  void error(const ir::SourceLoc& loc, const std::string& message);

  // Texture support (emit_texture.cpp).
  Id sampler_var(uint32_t stage);
  ir::SamplerType sampler_type(uint32_t stage) const;
  // `bias`: texldb's lod bias (implicit lod plus bias); `lod`: texldl's explicit lod
  // (OpImageSampleExplicitLod); `grad`: texldd's gradients (vec4 d/dx, d/dy of the
  // coordinates), as explicit Grad operands. At most one of them.
  Id sample(uint32_t stage, Id coord_vec4, std::optional<Id> bias = std::nullopt,
            std::optional<Id> lod = std::nullopt,
            std::optional<std::pair<Id, Id>> grad = std::nullopt);
  bool fetches(uint32_t stage) const;               // CodegenOptions::stage_fetch_unorm8 applies
  uint32_t sampler_binding(uint32_t stage) const;   // 2 + s#, or 19 + s# in a vertex program
  Id fetch_unorm8(Id sampled_image, Id coord_vec2); // the texel's k/255.0f
  Id point_texel_unorm8(Id sampled_image, Id coord_vec2); // its UNORM value, as the device has it
  Id clamp_uv01(Id coord_vec2); // NClamp(uv, 0, 1): u in [0, 1] kept, NaN → 0
  void kill_if_any_negative(Id value, int components);
  Id texcoord_input(uint32_t m); // TC(m)
  Id pad_value_[2] = {0, 0};     // texm3x2pad / texm3x3pad results (u', v')
  uint32_t pad_count_ = 0;

  // Flow state (emit_flow.cpp).
  struct FlowFrame {
    enum class Kind { If, Loop, Rep } kind;
    Id merge = 0, else_label = 0, cont = 0, header = 0;
    Id counter = 0;  // Private int: iterations left
    Id step = 0;     // loop: aL increment
    Id saved_al = 0; // loop: aL before the loop, restored after it
    bool has_else = false;
  };
  std::vector<FlowFrame> flow_;
  std::map<uint32_t, Id> label_fns_; // l# → function id
  std::set<uint32_t> labels_defined_;
  bool routine_ended_ = false; // a top-level ret ended the current routine
  Id label_fn(uint32_t label);
  Id clamp_int(Id v, int32_t lo, int32_t hi);
  // Loop and rep iterations the invocation has completed (ir::flow::kIterationBudget).
  Id iterations_var();
  Id iterations_var_ = 0;
  FlowFrame* innermost_loop();
  // The constructs of emit_flow, one an opening or closing instruction.
  void branch_if_open(Id target);
  Id bool_operand(const ir::SrcOperand& s); // b#, or !b#
  void begin_loop(FlowFrame::Kind kind, uint32_t int_reg);
  bool end_loop(const ir::Instruction& ins, FlowFrame::Kind kind);
  void open_if(Id cond);
  bool else_branch(const ir::Instruction& ins);
  bool end_if(const ir::Instruction& ins);
  bool leave_loop(const ir::Instruction& ins, Id cond); // cond 0: always
  void call_if(const ir::Instruction& ins);             // callnz
  void clear_phase_alpha();
  void end_routine_or_block(); // ret
  bool begin_subroutine(const ir::Instruction& ins);

  // ---- shader models 2.x and 3.0 (emit_predication.cpp) ----
  // x `c` y by ir::flow::compare, at width n (1: bool, 4: bvec4).
  Id compare(ir::flow::Comparison c, Id x, Id y, int n);
  Id first_component(const ir::SrcOperand& s);     // if_comp / break_comp operands
  Id p0_var();                                     // Private bvec4
  Id predicate_component(const ir::SrcOperand& p); // bool: p0.c, negated by !p0
  Id predicate_mask(const ir::SrcOperand& p);      // bvec4: "(p0.swz)" per destination component
  void emit_setp(const ir::Instruction& ins);
  Id misc_input(uint32_t index); // vPos, vFace
  Id p0_var_ = 0, frag_coord_var_ = 0, front_facing_var_ = 0;

  // D3DRS_SRGBWRITEENABLE (emit_srgb.cpp): a colour output's R, G, B encoded to sRGB
  // (CodegenOptions::srgb_write), from a Private table of the thresholds made once.
  Id srgb_encode(Id color_vec4);
  Id srgb_table_ = 0;

  // Interface and resources (emit_module.cpp).
  std::map<std::pair<ir::RegFile, uint32_t>, Id> regs_, inputs_;
  std::map<uint32_t, Id> samplers_;
  std::vector<InterfaceVar> interface_;
  std::vector<Id> interface_ids_;
  std::set<uint32_t> consts_read_;
  std::map<uint32_t, std::array<float, 4>> block_defs_; // ShaderModule::block_defs
  bool const_relative_ = false;
  Id uniform_var_ = 0, uniform_block_ = 0; // created in begin_module, sized at the end
  Id spec_max_value_ = 0;
  std::vector<SpecConstantInfo> spec_info_;
  Id spec_float(uint32_t spec_id, float default_value, const std::string& name);
  // Block members: 0 c[], then vs_2_0: 1 i[16], 2 b[16]; ps_1_x: 1 bumpenv[16].
  static constexpr uint32_t kMemberFloat = 0, kMemberInt = 1, kMemberBool = 2, kMemberBump = 1;
  uint32_t float_count_ = 0;
  UniformBlockInfo layout_; // uniform_block_layout's, set by declare_uniforms
  bool writes_depth_ = false, uses_kill_ = false;
  Id depth_out_var_ = 0;
  Id fn_main_ = 0;

  // CodegenOptions::trace (emit_trace.cpp): whether this module traces, the Private bool
  // "this invocation is the traced pixel" the entry point sets, the buffer, the instructions
  // that record.
  bool tracing() const;
  void trace_store(const PendingStore& st); // after st's register was written
  void trace_begin_entry();                 // in the entry point, before d3d_main runs
  void declare_trace_buffer();
  Id trace_flag_ = 0, trace_var_ = 0, trace_ptr_vec4_ = 0, trace_ptr_uint_ = 0;
  std::vector<uint32_t> trace_points_;

private:
  void begin_module();
  void declare_uniforms();
  void emit_code();
  void emit_entry();
  Id output_var(const InterfaceVar& iv, Id type);
  void flush(std::vector<PendingStore>& pending);
};

} // namespace tierlift::codegen
