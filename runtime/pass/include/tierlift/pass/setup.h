// A pass from typed settings: what `tierlift run` asks for (programs, constants, inputs,
// textures, sampler state, conventions) becomes one pass::Pass, prepared once and drawn by
// any device. The CLI parses its flags into these settings (cli/run_flags.h); tests build
// them directly.
//
// Typical use (e.g. Listings 3 + 4 over a built-in texture, RGBA32F):
//   RunRequest r;
//   r.vs = std::make_shared<ir::Program>(vs);  r.ps = std::make_shared<ir::Program>(ps);
//   r.width = r.height = 64;  r.format = img::Format::RGBA32F;
//   r.constants.push_back({StageMask::Vertex, ir::RegFile::Const, 0, {0.0078125f, 0, 0, 0}});
//   r.attrs.push_back({ir::RegFile::Input, 3, {0, 0, 0, 1}, true});   // v3 = the quad uv
//   for (uint32_t s = 0; s < 4; ++s) r.textures.push_back({s, "builtin:noise:64x64"});
//   r.filter = Filter::Linear;  r.address = AddressMode::Clamp;
//   ir::Result<Pass> pass = prepare_pass(r);
//
// Rules:
//   * Geometry is always the full-screen quad. With a vertex program, its position input
//     (pass.h, position_input) gets the quad's corners, attrs feed the other inputs (quad_uv:
//     (0,0) top-left … (1,1) bottom-right), and inputs not given read (0,0,0,1). Without one,
//     the pixel stage's v#/t# are the constants of `inputs` at every pixel (default 0), but
//     with texcoords_from_quad a t# not given is the quad's uv (input_sources.h).
//   * Constants: a c#/i#/b# a listing reads that is neither given nor def'd is an ERROR
//     naming the register (a forgotten --const otherwise silently gives a black image);
//     reads through a0/aL cannot be checked and only warn. Constants for StageMask::Both go
//     to both stages. def in the listing overrides a given value, as in D3D9.
//   * Textures: every sampler stage the pixel listing samples (ps_2_0: s#; ps_1_x: the
//     stage of each texture instruction) should be bound; an unbound one warns and reads
//     (0,0,0,1). Each source is read once. `filter` and `address` apply to every stage.
//     Defaults are D3D9's sampler defaults: point, wrap.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"

namespace tierlift::pass {

enum class StageMask : uint8_t { Both, Vertex, Pixel };

// One API-set constant: [vs:|ps:]cN=x,y,z,w | iN=a,b,c,d | bN=true|false. prepare_pass
// writes it into the ConstantBank of each stage it names.
struct ConstSetting {
  StageMask stage = StageMask::Both;
  ir::RegFile file = ir::RegFile::Const; // Const, ConstInt or ConstBool
  uint32_t index = 0;
  Vec4 f{0, 0, 0, 0};
  std::array<int32_t, 4> i{};
  bool b = false;
};

// A pixel-stage input v#|t# (without a vertex program) or a vertex input vN (with one).
struct RegisterSetting {
  ir::RegFile file = ir::RegFile::Input; // Input (v#) or Texture (t#)
  uint32_t index = 0;
  Vec4 value{0, 0, 0, 1};
  bool quad_uv = false; // vertex inputs only: the quad's uv instead of `value`
};

// A texture for sampler stage `sampler`: a file or builtin spec (img::load_texture).
struct TextureSetting {
  TextureSetting() = default;
  TextureSetting(uint32_t s, std::string src, std::shared_ptr<const img::Image> im = nullptr)
      : sampler(s), source(std::move(src)), image(std::move(im)) {}
  uint32_t sampler = 0;
  std::string source;                      // file or builtin spec (img::load_texture)
  std::shared_ptr<const img::Image> image; // when set: this image, `source` only names it
};

// A TextureSetting's source names a cube or volume texture by its layers' sources:
// "cube:+X,−X,+Y,−Y,+Z,−Z" (six files or builtin specs, D3D9's face order) or
// "volume:S0,S1,…" (the slices from w = 0 up), or a 2D texture's mip chain by its levels'
// sources, "mips:L0,L1,…" (level 0 first, each level half the previous, mip_chain.h). Any
// other source is one 2D texture.
struct LayeredSources {
  TextureShape shape = TextureShape::Tex2D;
  std::vector<std::string> sources; // one for a 2D texture
  bool mip_levels = false;          // "mips:": `sources` are the levels of one 2D texture
};
LayeredSources layered_sources(const std::string& source);

// texbem/texbeml's 2×2 bump-environment matrix of texture stage `stage` (D3DTSS_BUMPENVMAT00,
// 01, 10, 11): u' = u + M00·du + M10·dv, v' = v + M01·du + M11·dv. Stages not given keep 0
// (texbem then samples at the unbumped coordinate, as a D3D9 device does by default).
struct BumpSetting {
  uint32_t stage = 0;
  std::array<float, 4> matrix{0, 0, 0, 0}; // M00, M01, M10, M11
};

struct ProbePoint {
  uint32_t x = 0, y = 0;
};

struct ProbeValue {
  uint32_t x = 0, y = 0;
  Vec4 value{}; // as stored
};

struct RunRequest {
  std::shared_ptr<const ir::Program> vs, ps; // validated listings; either may be null
  uint32_t width = 256, height = 256;
  img::Format format = img::Format::RGBA8;
  std::vector<ConstSetting> constants;
  std::vector<RegisterSetting> inputs; // used only without a vertex program
  // Without a vertex program: every t# the pixel listing names and `inputs` does not set is
  // the quad's uv, not 0 (input_sources.h). `tierlift run` sets it.
  bool texcoords_from_quad = false;
  std::vector<RegisterSetting> attrs; // used only with a vertex program
  std::vector<TextureSetting> textures;
  std::vector<BumpSetting> bump_matrices;
  Filter filter = Filter::Point;
  AddressMode address = AddressMode::Wrap;
  ir::Conventions conventions;
  // Mip chains: every 2D texture given as one image gets `generated_levels` levels made by
  // pass::generate_mips (0: the full chain; 1: none, the default), and every stage takes
  // `mip` (MIPFILTER, MIPMAPLODBIAS, MAXMIPLEVEL), as `filter` and `address`.
  uint32_t generated_levels = 1;
  MipState mip;
  FrontFace front_face = FrontFace::Clockwise; // the winding vFace calls front
  std::vector<ProbePoint> probes;
  unsigned threads = 0; // CPU device: 0 = every core
  // Render targets oC0..oC(n−1) (D3D9 MRT, 1..4), all of the request's size and format.
  uint32_t color_targets = 1;
  // D3DSAMP_SRGBTEXTURE on every sampler stage, D3DRS_SRGBWRITEENABLE (NUMERICS.md, sRGB).
  bool srgb_texture = false, srgb_write = false;
  // ZENABLE / ZWRITEENABLE / ZFUNC (`tierlift run --depth-*`): the pass's depth state; the
  // depth buffer's clear value and starting image are the graph's (effects::SinglePassDepth).
  DepthStencilState depth_stencil;
};

// Problems, kept apart by where their positions point: into the vertex listing's
// SourceManager, the pixel listing's, or nowhere (flags, textures, the draw). What a caller
// that renders them collects (add_by_listing); prepare_pass itself returns one ir::Result.
struct RunDiagnostics {
  ir::DiagnosticSink vs, ps, other;
  bool has_errors() const { return vs.has_errors() || ps.has_errors() || other.has_errors(); }
};
// Rule of the `other` error for a texture file that does not exist (an I/O problem, as
// opposed to a file that exists but does not decode).
inline constexpr std::string_view kRuleTextureMissing = "texture-missing";
// A builtin: texture spec that names no built-in texture or has a bad size.
inline constexpr std::string_view kRuleTextureSpec = "texture-spec";
// A c# setting no stage of the run has a register for (ps:c999).
inline constexpr std::string_view kRuleConstantRange = "constant-range";
// Errors of these rules come from a flag's value, not from the listings: usage errors.
constexpr bool is_usage_rule(std::string_view rule) {
  return rule == kRuleTextureMissing || rule == kRuleTextureSpec || rule == kRuleConstantRange;
}

// The pass `request` describes, textures loaded (each source once), or the errors why not;
// warnings never stop it and ride along with the pass. Checks the size too
// (1..img::kMaxDimension); running out of memory for the textures is an error ("memory"). The
// vertex and the pixel listing come from two SourceManagers, and one flat list cannot say which a
// position points into, so a diagnostic positioned in a listing names it as its subject
// (kVsListing, kPsListing; a positioned diagnostic's subject is otherwise unused): add_by_listing
// sorts them back for rendering.
inline constexpr std::string_view kVsListing = "vs";
inline constexpr std::string_view kPsListing = "ps";
ir::Result<Pass> prepare_pass(const RunRequest& request);
// Adds `ds` (prepare_pass's) to `diags`: each to the sink of the listing its subject names,
// subject cleared, as it was reported; the others to diags.other.
void add_by_listing(RunDiagnostics& diags, const std::vector<ir::Diagnostic>& ds);

// The stored values at `probes` (each inside `image`).
std::vector<ProbeValue> read_probes(const img::Image& image, const std::vector<ProbePoint>& probes);

} // namespace tierlift::pass
