// One draw, described once for every device: the programs, one constant bank per stage, the
// sampler stages with their sampler and texture-stage state, the geometry, the viewport, the
// blend and the output-merger state, the conventions. The CPU interpreter (cpu::draw), the
// Vulkan device (vulkan::Device::draw) and the analytic model all consume this type; none of
// them defines its own. Each pass of an effect graph holds one (effects::PassDesc::draw, its
// images bound by the device that owns them); `tierlift run` builds one from its flags
// (setup.h) and moves it into a graph of one pass (effects/single_pass.h), so every device is
// reached through effects::PassDevice.
//
// Room for what comes next is made here as state, not as implementations: several render
// targets, a depth/stencil buffer with D3D9's stencil state, fixed-function texture stages.
// A device checks the state it cannot honour with check_supported (below) and refuses the
// pass with an error instead of drawing something else. Frames that feed back are a graph
// property (effects/graph.h, TextureDesc::feedback).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "tierlift/image/image.h"
#include "tierlift/ir/conventions.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/addressing.h"
#include "tierlift/pass/mip_lod.h"
#include "tierlift/pass/registers.h"

namespace tierlift::pass {

enum class Filter : uint8_t { Point, Linear };

// D3DSAMP_* state of one sampler stage. The defaults are D3D9's: POINT, WRAP, border colour
// 0x00000000.
struct SamplerState {
  Filter filter = Filter::Point;
  AddressMode address_u = AddressMode::Wrap;
  AddressMode address_v = AddressMode::Wrap;
  AddressMode address_w = AddressMode::Wrap; // D3DSAMP_ADDRESSW: volume textures' third axis
  Vec4 border_color{0, 0, 0, 0};
  // MIPFILTER, MIPMAPLODBIAS, MAXMIPLEVEL (mip_lod.h): which levels of a mip chain a read takes.
  MipState mip;
  // D3DSAMP_SRGBTEXTURE: an RGBA8 texture's R, G, B are decoded from sRGB to linear before
  // filtering (pass/srgb.h; NUMERICS.md S1, S2). Off by default, as in D3D9.
  bool srgb = false;
};

// POINT filtering with CLAMP addressing on both axes: each read takes one texel, and never
// from beyond the edge. The Vulkan device reads an RGBA8 texture sampled so from its stored
// bytes, without a float copy (codegen::CodegenOptions::stage_fetch_unorm8), and the memory
// plan (effects/memory_plan.h) counts no copy for it.
inline bool point_clamped(const SamplerState& s) {
  // MIPFILTER POINT or LINEAR: the read takes a level by the lod, which the clamped
  // coordinate's gradients would change.
  return s.filter == Filter::Point && s.address_u == AddressMode::Clamp &&
         s.address_v == AddressMode::Clamp && s.mip.filter == MipFilter::None;
}

// The kind of texture a stage holds (D3DRTYPE_TEXTURE, _CUBETEXTURE, _VOLUMETEXTURE).
enum class TextureShape : uint8_t { Tex2D, Cube, Volume };

// The face order of a cube texture: D3DCUBEMAP_FACE_POSITIVE_X … NEGATIVE_Z, which is also
// Vulkan's array-layer order of a cube view (NUMERICS.md, cube maps).
enum class CubeFace : uint8_t { PosX, NegX, PosY, NegY, PosZ, NegZ };

// What one sampler stage holds: a texture (shared, so one image can be bound to several
// stages as Listing 4 does), the sampler state, and the ps_1_x texture-stage state.
// A cube or volume texture holds its images in `layers` (a cube: the six faces in CubeFace
// order, all square and of one size; a volume: its slices from w = 0 up, all of one size),
// and `image` is layers[0], so that "is a texture bound" reads the same for every shape.
struct TextureBinding {
  std::shared_ptr<const img::Image> image; // null: unbound, reads (0, 0, 0, 1)
  SamplerState sampler;
  StageState stage;
  TextureShape shape = TextureShape::Tex2D;
  std::vector<std::shared_ptr<const img::Image>> layers = {}; // Cube and Volume only
  // A 2D texture's mip chain, level 0 (= image) first, each level max(1, floor(previous / 2))
  // on each side (mip_chain.h checks and generates them); empty: one level, `image`.
  std::vector<std::shared_ptr<const img::Image>> levels = {};
};

// A cube or volume binding from its layers (checked: a cube has six square faces of one
// size, a volume at least one slice, all of one size); an error says what is wrong.
ir::Result<TextureBinding> layered_binding(TextureShape shape,
                                           std::vector<std::shared_ptr<const img::Image>> layers);

// Whether a read of `b` takes its level by a level of detail: a mip chain of more than one
// level with MIPFILTER POINT or LINEAR (NONE reads level MAXMIPLEVEL, no lod needed).
inline bool reads_by_lod(const TextureBinding& b) {
  return b.levels.size() > 1 && b.sampler.mip.filter != MipFilter::None;
}

inline constexpr uint32_t kMaxSamplers = 16;
// Vertex texture fetch (vs_3_0 texldl, NUMERICS.md F14): the vertex stage has its own four
// samplers, s0..s3 in the listing, D3DVERTEXTEXTURESAMPLER0..3 on the API side, which Direct3D
// 9 numbers 257..260 in SetTexture and SetSamplerState. Where one number names a sampler of
// either stage (pass::TextureSetting::sampler, effects::TextureBind::stage) it is that one:
// 0..15 a pixel stage, 257 + N the vertex stage's sN (Pass::vertex_textures[N]).
inline constexpr uint32_t kMaxVertexSamplers = 4;
inline constexpr uint32_t kVertexSampler0 = 257;
constexpr bool is_vertex_sampler(uint32_t stage) {
  return stage >= kVertexSampler0 && stage < kVertexSampler0 + kMaxVertexSamplers;
}
// Arrays that hold both stages' samplers side by side (vulkan::StageTextures) put the pixel
// stage's s# at # and the vertex stage's sN at kMaxSamplers + N: sampler_slot maps a sampler
// number (above) to its slot, kSamplerSlots when it names none.
inline constexpr uint32_t kSamplerSlots = kMaxSamplers + kMaxVertexSamplers;
constexpr uint32_t sampler_slot(uint32_t stage) {
  if (stage < kMaxSamplers) return stage;
  return is_vertex_sampler(stage) ? kMaxSamplers + (stage - kVertexSampler0) : kSamplerSlots;
}

struct Pass;
// Whether any pixel-stage sampler of `pass` holds a mip chain read by lod (reads_by_lod): the
// pixel stage then takes gradients by quads. (The vertex stage reads with texldl only, whose
// lod is explicit.)
bool reads_mips_by_lod(const Pass& pass);
// The binding a sampler number (0..15, or 257 + N: is_vertex_sampler) names in `pass`:
// pass.textures[stage] or pass.vertex_textures[stage − 257]; nullptr for any other number.
TextureBinding* sampler_binding(Pass& pass, uint32_t stage);
const TextureBinding* sampler_binding(const Pass& pass, uint32_t stage);

enum class BlendMode : uint8_t {
  Replace,             // dst = src
  OneOne,              // dst = src + dst
  SrcAlphaOne,         // dst = src·src.a + dst
  SrcAlphaInvSrcAlpha, // dst = src·src.a + dst·(1 − src.a)
};

// D3DVIEWPORT9. width/height 0 mean "the render target's size".
struct Viewport {
  int32_t x = 0, y = 0;
  uint32_t width = 0, height = 0;
  float min_z = 0.0f, max_z = 1.0f;
};

// D3DRS_SCISSORTESTENABLE with IDirect3DDevice9::SetScissorRect: only pixels with
// x0 ≤ x < x1 and y0 ≤ y < y1 are drawn (a RECT: right and bottom exclusive), within the
// viewport and the target.
struct ScissorRect {
  int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// D3DCMPFUNC and D3DSTENCILOP, for the depth/stencil state below.
enum class CompareFunc : uint8_t {
  Never,
  Less,
  Equal,
  LessEqual,
  Greater,
  NotEqual,
  GreaterEqual,
  Always
};
enum class StencilOp : uint8_t { Keep, Zero, Replace, IncrSat, DecrSat, Invert, Incr, Decr };

// D3DRS_ZENABLE … D3DRS_STENCILWRITEMASK (one-sided stencil). Disabled by default: no
// depth/stencil buffer is bound and nothing is tested.
struct DepthStencilState {
  bool depth_test = false, depth_write = false;
  CompareFunc depth_func = CompareFunc::LessEqual;
  bool stencil_test = false;
  CompareFunc stencil_func = CompareFunc::Always;
  StencilOp stencil_fail = StencilOp::Keep, stencil_depth_fail = StencilOp::Keep,
            stencil_pass = StencilOp::Keep;
  uint32_t stencil_ref = 0, stencil_read_mask = 0xffffffffu, stencil_write_mask = 0xffffffffu;
  bool enabled() const { return depth_test || depth_write || stencil_test; }
};

// Corners of the full-screen quad in clip space, in the order top-left, top-right,
// bottom-left, bottom-right: (−1, 1), (1, 1), (−1, −1), (1, −1), z = 0, w = 1.
inline constexpr std::array<Vec4, 4> kQuadCorners{Vec4{-1, 1, 0, 1}, Vec4{1, 1, 0, 1},
                                                  Vec4{-1, -1, 0, 1}, Vec4{1, -1, 0, 1}};
// (u, v, 0, 1) at the same corners: (0, 0) top-left … (1, 1) bottom-right.
inline constexpr std::array<Vec4, 4> kQuadUV{Vec4{0, 0, 0, 1}, Vec4{1, 0, 0, 1}, Vec4{0, 1, 0, 1},
                                             Vec4{1, 1, 0, 1}};
// The quad's two triangles (indices into the corners above); they share the diagonal from
// top-right to bottom-left.
inline constexpr std::array<std::array<uint32_t, 3>, 2> kQuadTriangles{
    std::array<uint32_t, 3>{0, 1, 2}, std::array<uint32_t, 3>{2, 1, 3}};

// Which executor the CPU device runs the pixel stage with (other devices ignore it). Auto:
// the block executor whenever it takes the program, else the per-pixel ShaderVM; Scalar:
// always the per-pixel ShaderVM (the reference). Both give the same image, bit for bit.
enum class Executor : uint8_t { Auto, Scalar };

// Which on-screen winding is the front face, the one ps_3_0's vFace reads as +1 (NUMERICS.md
// F5). Clockwise is Direct3D 9's (D3DCULL_CCW, the default cull mode, culls the other one);
// CounterClockwise is for a scene drawn mirrored (a flipped viewport or reflected geometry).
// Nothing is culled either way.
enum class FrontFace : uint8_t { Clockwise, CounterClockwise };

// One pass. Which vertex stage runs:
//   * vertex_program set: it runs once per entry of `vertices` (its inputs v#);
//   * no vertex program, `transformed` not empty: those are the vertex outputs, as with
//     D3D9's pre-transformed vertices but in clip space (pos is divided by w);
//   * neither: the full-screen quad with pixel-stage inputs `constant_inputs`, exactly
//     as given at every pixel (no interpolation, so constants stay bit-exact).
// `triangles` index the vertices; empty means consecutive triples (0,1,2), (3,4,5), ….
// Which pixel stage runs: pixel_program, or none (oD0 passes through).
struct Pass {
  std::shared_ptr<const ir::Program> vertex_program;
  std::shared_ptr<const ir::Program> pixel_program;
  ConstantBank vs_constants, ps_constants;
  std::array<TextureBinding, kMaxSamplers> textures{}; // pixel-stage sampler stages
  // The vertex stage's samplers (vs_3_0 texldl; element N is the listing's sN, D3D9's
  // D3DVERTEXTEXTURESAMPLER N): read with the pixel stage's sampling rules, at the lod texldl
  // gives. Unbound ones read (0, 0, 0, 1), as an unbound pixel stage. 2D textures (a mip chain
  // allowed); the texture-stage state (`stage`) is ps_1_x's and means nothing here.
  std::array<TextureBinding, kMaxVertexSamplers> vertex_textures{};

  std::vector<VertexInput> vertices;
  std::vector<VertexOutput> transformed;
  std::vector<std::array<uint32_t, 3>> triangles;
  PixelInput constant_inputs;

  Viewport viewport;
  std::optional<ScissorRect> scissor; // none: the scissor test is off
  BlendMode blend = BlendMode::Replace;
  FrontFace front_face = FrontFace::Clockwise;
  ir::Conventions conventions;
  Executor executor = Executor::Auto;

  // Output merger beyond one colour target (D3D9 MRT: oC0..oC3 into as many targets).
  uint32_t color_targets = 1;
  DepthStencilState depth_stencil;
  // A pixel stage given as SPIR-V (a GLSL pass compiled by tierlift/glsl) that a device
  // draws instead of pixel_program's translation. pixel_program is then the pass's ps_2_0
  // twin: the same computation in D3D9 assembly, whose interface the SPIR-V follows (t# at
  // Location #, s# at binding 2 + #, oC0 at Location 0; docs/glsl.md). A device that cannot
  // run SPIR-V refuses the pass (check_supported); it never draws the twin in its place
  // silently — the effect layer decides that (effects::CpuPassDevice, documented there).
  std::shared_ptr<const std::vector<uint32_t>> pixel_spirv;
  // D3DRS_SRGBWRITEENABLE: each colour output is encoded from linear to sRGB before blending
  // and the store, on RGBA8 targets (NUMERICS.md S3); float targets take it unchanged.
  bool srgb_write = false;
};

// What a draw took, for the report (effects::PassDevice::draw returns it); counters a
// device does not keep stay 0.
struct DrawReport {
  double setup_ms = 0; // programs, pipelines, uploads
  double draw_ms = 0;  // the draw itself (on a GPU that queues it: the recording)
  uint64_t pixels_shaded = 0, pixels_killed = 0;
};

// What a device can draw beyond one colour target with programmable stages.
struct Capabilities {
  uint32_t max_color_targets = 1;
  bool depth_stencil = false;
  bool spirv_pixel_stage = false; // Pass::pixel_spirv
};

// An error (rule "unsupported", subject `device`) for the first thing `pass` asks of a
// device with `caps` that it cannot do; ok otherwise.
ir::Status check_supported(const Pass& pass, const Capabilities& caps, std::string_view device);

// The vertex program as the pass's pixel program reads it: a vs_1_x/2_x's oFog moved to the
// slot a ps_3_0 reads fog0 from (ir::feed_fog, NUMERICS.md F6). nullopt when the pass's own
// vertex program serves unchanged (or there is none).
std::optional<ir::Program> fed_vertex_program(const Pass& pass);

// The quad's vertex inputs, one rule for every caller (tierlift run, the effect graph, the
// devices' tests). D3D9 feeds the position to the input declared dcl_position with usage
// index 0 (v0 when the listing declares no position, D3D8 style); the quad's uv goes to
// every input declared dcl_texcoord (any usage index), so a listing may read it under
// several registers.
uint32_t position_input(const ir::Program& vertex_program);
std::vector<uint32_t> texcoord_inputs(const ir::Program& vertex_program);

// Fills pass.vertices with the full-screen quad's four corners: `position_register` gets
// kQuadCorners, every other input reads (0, 0, 0, 1); and sets pass.triangles.
void set_full_screen_quad(Pass& pass, uint32_t position_register);
// The same for pass.vertex_program, with kQuadUV at every texcoord_inputs register.
void set_full_screen_quad_uv(Pass& pass);

} // namespace tierlift::pass
