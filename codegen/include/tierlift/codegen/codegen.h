// ir::Program → SPIR-V (Vulkan 1.1, SPIR-V 1.3). The resource and interface mapping is
// docs/spirv-mapping.md; every emitted module is checked by spirv-val in-process and a
// module that fails is reported as an error, never returned.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/codegen/unorm8_decode.h"
#include "tierlift/ir/conventions.h"
#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"

namespace tierlift::codegen {

// Fixed resource bindings (descriptor set 0); see docs/spirv-mapping.md.
inline constexpr uint32_t kDescriptorSet = 0;
inline constexpr uint32_t kVertexConstantsBinding = 0;
inline constexpr uint32_t kPixelConstantsBinding = 1;
inline constexpr uint32_t kFirstSamplerBinding = 2; // binding = 2 + sampler/stage number
inline constexpr uint32_t kTraceBinding = 18;       // CodegenOptions::trace's storage buffer
// A vs_3_0's samplers (texldl, vertex texture fetch) bind at 19 + s#: apart from the pixel
// stage's, since one descriptor set serves both stages (NUMERICS.md F14).
inline constexpr uint32_t kFirstVertexSamplerBinding = 19;
// Interface locations shared by both stages: tN/oTN at N, vN/oDN at 8 + N, oFog at 10.
inline constexpr uint32_t kTexCoordLocation = 0;
inline constexpr uint32_t kColorLocation = 8;
inline constexpr uint32_t kFogLocation = 10;
// Specialization constant ids.
inline constexpr uint32_t kSpecFlipY = 0;        // float, multiplies oPos.y (default -1)
inline constexpr uint32_t kSpecPixelOffsetX = 1; // float, clip-space x += value * w
inline constexpr uint32_t kSpecPixelOffsetY = 2; // float, clip-space y += value * w
inline constexpr uint32_t kSpecPs1xMaxValue = 3; // float, ps_1_x register range clamp

enum class KillMode {
  Kill,   // OpKill (core SPIR-V; the invocation ends, no helper remains)
  Demote, // OpDemoteToHelperInvocation (SPV_EXT_demote_to_helper_invocation)
};

// CodegenOptions::trace: the pixel whose every instruction result the pixel module records.
// Entry i of the storage buffer (binding `binding`, set 0) belongs to instruction i of
// Program::code: { vec4 value; uint hits; } at 32·i (value at +0, hits at +16). After an
// instruction stores its destination register, the invocation at pixel (x, y) (gl_FragCoord
// truncated: pixel x spans [x, x + 1)) writes the whole register there (a0: its integers
// as floats) and adds 1 to hits; other invocations write nothing. The buffer must start at
// zero; hits then counts how often the instruction ran (loops: value is the last run's).
struct TracePixel {
  uint32_t x = 0, y = 0;
  uint32_t binding = kTraceBinding;
};
inline constexpr uint32_t kTraceEntryBytes = 32;

struct CodegenOptions {
  ir::Conventions conventions;
  // Default values of the position fix-up specialization constants. D3D9 pixel centres on
  // Vulkan need +1/width and +1/height (half a pixel in NDC); 0 leaves the fix-up to the
  // viewport (x + 0.5, y + 0.5). flip_y = true negates y (D3D +y up, Vulkan +y down).
  bool flip_y = true;
  float pixel_offset_x = 0.0f, pixel_offset_y = 0.0f;
  KillMode kill = KillMode::Kill;
  // ps_1_1…1_3 have no sampler declarations: the texture type of each stage (2D default).
  std::array<ir::SamplerType, 16> stage_texture_type{};
  // ps_1_1…1_3 D3DTTFF_PROJECTED per stage: tex divides the coordinate by its w.
  std::array<bool, 16> stage_projected{};
  // Per stage: the stage reads an RGBA8 UNORM texture through a POINT, CLAMP/CLAMP sampler.
  // A 2D read there fetches the texel itself instead of sampling: the index is the one point
  // sampling takes (floor(fl32(u·N)), NaN → 0, clamped to the edge) and each stored byte k
  // becomes k/255.0f correctly rounded, the value a float copy of the texture would hold, in
  // a few float operations (emit_texture.cpp). The device then binds the RGBA8 image itself.
  // SamplerInfo::fetch_unorm8 says which stages got it.
  std::array<bool, 16> stage_fetch_unorm8{};
  // Per stage: the stage's sampler is POINT with CLAMP/CLAMP addressing. A 2D read that
  // samples (every one but a stage_fetch_unorm8 read, which clamps itself) clamps (u, v) to
  // [0, 1] first, NaN → 0. Inside [0, 1] that changes nothing, and outside every u picks the
  // edge texel, as CLAMP does; but lavapipe's point sampler turns a u·N beyond the int range
  // into texel 0 (u = 1e30 read texel 0 of an RGBA32F texture, where the interpreter reads
  // the last), and a clamped u never gets there.
  std::array<bool, 16> stage_point_clamped{};
  // The same for a vs_3_0's own samplers s0..s3 (texldl, vertex texture fetch, NUMERICS.md
  // F14): lavapipe's vertex stage reads texel 0 at u = 1e10 under POINT/CLAMP as its pixel
  // stage does, where CLAMP (and the interpreter) give the edge texel.
  std::array<bool, 4> vertex_point_clamped{};
  // How those reads turn the device's value into k/255.0f (unorm8_decode.h): the Vulkan
  // device chooses by reading every level once. The default is right on every device whose
  // value is within a few ulps of k/255.
  Unorm8Decode unorm8_decode = Unorm8Decode::RoundAndRebuild;
  // The device's point sampler with CLAMP_TO_EDGE picks texel floor(fl32(u·N)), clamped to
  // [0, N − 1], for every u in [0, 1] on each axis, as the interpreter does (lavapipe: one
  // float multiply and a floor; not a GPU, whose sub-texel coordinates are fixed point). A
  // stage_fetch_unorm8 read then samples the RGBA8 image at (u, v) clamped to [0, 1] (NaN →
  // 0; every u outside picks the same edge texel as before) and decodes the value as the
  // fetch does, instead of computing the index and fetching.
  bool point_sampling_floors = false;
  // Per stage, the c# values the module will run with: the constants the device binds (a
  // def still wins). The Vulkan device fills both and caches a prepared draw under its
  // constants (draw_cache.h), so the module never meets others. Unset: nothing is known.
  // Known, the module is specialised for them, each time to the same value bit for bit:
  //  * a c# whose four components hold the same bits (a weight replicated across rgba, as
  //    the glow's listings read theirs), read without relative addressing, loads its x and
  //    replicates it; lavapipe runs that far faster than a vec4 uniform read (the glow's
  //    blur passes: 1.3×);
  //  * in a product with a c# (read without relative addressing, swizzled, negated or not),
  //    the "0 × anything = +0" rule (NUMERICS.md rule 8) tests only the other factor in the
  //    components that never compare equal to zero: a non-zero exponent field (normal,
  //    infinite or NaN; not ±0, and not a denormal, which Rounding::Llvmpipe reads as zero);
  //    lavapipe: the glow's blur passes ~3 % faster;
  //  * a pixel module leaves out what ir::plain_values proves changes nothing for these
  //    constants and the stage_fetch_unorm8 reads: the zero test of a product whose factors
  //    are both plain (rule::mul_plain), a ps_1_x range clamp that no plain result reaches
  //    (SpecId 3 may then be raised, not lowered, from conventions.ps1x_max_value) and the
  //    [−1, 1] clamp of a ps_1_x constant inside it; lavapipe, dx8 RGBA8 glow: 1.43 → 1.31 of
  //    the GLSL peer.
  std::optional<std::vector<std::array<float, 4>>> known_vs_constants, known_ps_constants;
  // Every def is read from the uniform block, at its register's slot, instead of being a
  // SPIR-V constant (ShaderModule::block_defs: the values the device writes there):
  // lavapipe's compiler folds arithmetic on constants to values the same arithmetic gives
  // differently at run time (NUMERICS.md, "Lavapipe workarounds": non-finite defs, exp2 and
  // log2 folded with the C library, denormal results kept where run time flushes them). The
  // Vulkan device sets it where its modules serve any constants
  // (vulkan::TextureSet::set_reuse_programs: `tierlift test`'s differential run).
  bool defs_in_block = false;
  bool optimize = false; // run spirv-opt's performance passes after validation
  // Pixel stage only (a vertex module ignores it): record one pixel's instruction results
  // (TracePixel). Unset, the module is exactly the one it always was.
  std::optional<TracePixel> trace;
  // Entry point name.
  std::string entry_point = "main";
  // Pixel stage: per colour output location (oC0..oC3; ps_1_x's r0 is location 0), encode R,
  // G, B from linear to sRGB before the output is written (D3DRS_SRGBWRITEENABLE on an RGBA8
  // target; NUMERICS.md S3): the byte rounding::srgb_encode_byte finds by the same eight-step
  // binary search over rounding::srgb_encode_thresholds, times rounding::kSrgbByteScale.
  std::array<bool, 4> srgb_write{};
};

enum class InterfaceKind {
  Input,   // vertex attribute / interpolated varying
  Output,  // varying / fragment colour
  BuiltIn, // Position, PointSize, FragDepth
};

struct InterfaceVar {
  InterfaceKind kind = InterfaceKind::Input;
  ir::RegFile file = ir::RegFile::Input; // the D3D register it carries
  uint32_t index = 0;
  uint32_t location = 0;   // for Input/Output
  uint32_t components = 4; // float components (vec4 except oFog)
  std::string builtin;     // "Position", "PointSize", "FragDepth"
  std::string name;        // "v0", "oT3", ...
  // D3D usage the variable carries: vertex inputs from their dcl (position, texcoord3, …);
  // varyings texcoordN (oT#/t#) or colorN (oD#/v#). A device binds vertex streams by it.
  std::optional<ir::DeclUsage> usage;
  uint8_t usage_index = 0;
};

// A stage's constant block in std140, the one description of its layout: the code generator
// declares the block from it (emit_module.cpp) and a device packs the bank into it
// (vulkan/uniforms.h). Members, each an array of 16-byte elements: vec4 c[] at 0; vs_2_0:
// ivec4 i[16], then uint b[16]; ps_1_x: vec4 bumpenv[16], two per texture stage — (M00, M01,
// M10, M11) and (lscale, loffset, 0, 0).
struct UniformBlockInfo {
  static constexpr uint32_t kStride = 16; // ArrayStride of every member
  static constexpr uint32_t kIntRegisters = 16, kBoolRegisters = 16;
  static constexpr uint32_t kBumpStages = 8, kBumpSlotsPerStage = 2;

  uint32_t set = kDescriptorSet, binding = 0;
  uint32_t float_count = 0;         // vec4 c[float_count] at offset 0
  uint32_t int_offset = 0;          // ivec4 i[16] (0 when absent)
  uint32_t bool_offset = 0;         // uint b[16] (0 when absent)
  uint32_t bump_offset = 0;         // ps_1_x: vec4 bumpenv[16] (0 when absent)
  uint32_t size_bytes = 0;          // 0: no block
  std::vector<uint32_t> float_used; // c# read by the program (after pruning)

  // Byte offsets of single values (component k = 0..3).
  static uint32_t float_at(uint32_t c, uint32_t k) { return kStride * c + 4 * k; }
  uint32_t int_at(uint32_t n, uint32_t k) const { return int_offset + kStride * n + 4 * k; }
  uint32_t bool_at(uint32_t n) const { return bool_offset + kStride * n; }
  uint32_t bump_matrix_at(uint32_t stage, uint32_t k) const {
    return bump_offset + kStride * kBumpSlotsPerStage * stage + 4 * k;
  }
  uint32_t bump_lscale_at(uint32_t stage) const { return bump_matrix_at(stage, 0) + kStride; }
  uint32_t bump_loffset_at(uint32_t stage) const { return bump_matrix_at(stage, 1) + kStride; }
};

// The layout of a block declaring `float_slots` c# elements (at least 1 when the block
// exists), the integer and boolean registers (vs_2_0) and the bump-environment states
// (ps_1_x). float_count is left to the caller (the registers in use, possibly 0).
UniformBlockInfo uniform_block_layout(uint32_t float_slots, bool has_int, bool has_bump);

struct SamplerInfo {
  uint32_t set = kDescriptorSet, binding = 0;
  uint32_t stage = 0; // s# / texture stage
  ir::SamplerType type = ir::SamplerType::Tex2D;
  bool fetch_unorm8 = false; // CodegenOptions::stage_fetch_unorm8 applied to this stage
};

struct SpecConstantInfo {
  uint32_t id = 0; // SpecId
  float default_value = 0.0f;
  std::string name; // "flip_y", "pixel_offset_x", ...
};

// The record a traced pixel module writes (CodegenOptions::trace).
struct TraceInfo {
  uint32_t set = kDescriptorSet, binding = kTraceBinding;
  uint32_t entries = 0;         // Program::code.size(): the buffer holds kTraceEntryBytes each
  std::vector<uint32_t> points; // the instructions that record (those storing a register)
};

struct ShaderModule {
  ir::ShaderStage stage = ir::ShaderStage::Vertex;
  std::vector<uint32_t> words;
  std::string entry_point;
  std::vector<InterfaceVar> interface;
  UniformBlockInfo uniforms;
  std::vector<SamplerInfo> samplers;
  std::vector<SpecConstantInfo> spec_constants; // all float, 4 bytes each
  bool writes_depth = false;
  bool uses_kill = false;
  std::optional<TraceInfo> trace; // set when CodegenOptions::trace applied
  // CodegenOptions::defs_in_block: c# slots of the uniform block that hold a def
  // (denormals already flushed as the module would), written over the bound constants.
  std::vector<std::pair<uint32_t, std::array<float, 4>>> block_defs;
};

// What linking-time pruning left out, one entry per item (for --explain).
struct PrunedItem {
  enum class Kind { VertexOutput, VertexInput, PixelInput, Constant, DeadInstruction } kind;
  ir::ShaderStage stage = ir::ShaderStage::Vertex;
  std::string what;   // "oT5", "v2", "c7", "add oT5, v3, c5"
  std::string reason; // "the pixel shader never reads t5"
  ir::SourceLoc loc;
};

struct CompiledPair {
  ShaderModule vs, ps;
  std::vector<PrunedItem> pruned;
};

// Compiles one program. Errors (unsupported construct, validator failure) go to diags with
// a position; the result is then nullopt.
std::optional<ShaderModule> compile(const ir::Program& program, const CodegenOptions& options,
                                    ir::DiagnosticSink& diags);

// Compiles a VS/PS pair, leaving out what the other stage never consumes.
std::optional<CompiledPair> compile_pair(const ir::Program& vs, const ir::Program& ps,
                                         const CodegenOptions& options, ir::DiagnosticSink& diags);

// One line per pruned item ("vertex: removed output oT5: the pixel shader never reads t5"),
// for --explain.
std::string explain(const std::vector<PrunedItem>& pruned);

// spirv-val with the Vulkan 1.1 target environment; a failure carries the validator's
// messages (subject "spirv-val").
ir::Status validate(const std::vector<uint32_t>& words);
// Human-readable disassembly (spirv-dis).
ir::Result<std::string> disassemble(const std::vector<uint32_t>& words);
// spirv-opt performance passes; on failure the words are unchanged.
ir::Status optimize(std::vector<uint32_t>& words);

} // namespace tierlift::codegen
