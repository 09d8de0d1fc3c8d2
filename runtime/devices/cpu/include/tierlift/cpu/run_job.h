// `tierlift run` as a library: one pass of one or two validated listings over the
// full-screen quad, built from typed options, drawn on the CPU device. The CLI only parses
// flags (with the parse_* helpers below) and prints; tests call run_job() directly.
//
// Typical use (e.g. Listings 3 + 4 over a built-in texture, RGBA32F):
//   RunRequest r;
//   r.vs = std::make_shared<ir::Program>(vs);  r.ps = std::make_shared<ir::Program>(ps);
//   r.width = r.height = 64;  r.format = img::Format::RGBA32F;
//   r.constants.push_back(*parse_const_setting("vs:c0=0.0078125,0,0,0", err));  ...
//   r.attrs.push_back(*parse_attr_setting("v3=quad-uv", err));
//   for (uint32_t s = 0; s < 4; ++s) r.textures.push_back({s, "builtin:noise:64x64"});
//   r.filter = Filter::Linear;  r.address = AddressMode::Clamp;
//   RunDiagnostics d;  RunResult out = run_job(r, d);   // out.image, out.probes
//
// Rules:
//   * Geometry is always the full-screen quad. With a vertex program, its dcl_position input
//     (v0 when the listing has no dcl, D3D8 style) gets the quad's corners in clip space,
//     --attr values feed the other inputs (quad-uv: (0,0) top-left … (1,1) bottom-right),
//     and inputs not given read (0,0,0,1). Without one, the pixel stage's v#/t# are the
//     constants of `inputs` at every pixel (default (0,0,0,0)).
//   * Constants: a c#/i#/b# a listing reads that is neither given nor def'd is an ERROR
//     naming the register (a forgotten --const otherwise silently gives a black image);
//     reads through a0/aL cannot be checked and only warn. Constants without a "vs:"/"ps:"
//     prefix go to both stages. def in the listing overrides a given value, as in D3D9.
//   * Textures: every sampler stage the pixel listing samples (ps_2_0: s#; ps_1_x: the
//     stage of each texture instruction) should be bound; an unbound one warns and reads
//     (0,0,0,1). `filter` and `address` apply to every stage. Defaults are D3D9's sampler
//     defaults: point, wrap.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/cpu/draw.h"
#include "tierlift/ir/diagnostic.h"

namespace tierlift::cpu {

enum class StageMask : uint8_t { Both, Vertex, Pixel };

// --const [vs:|ps:]cN=x,y,z,w | iN=a,b,c,d | bN=true|false
struct ConstSetting {
  StageMask stage = StageMask::Both;
  ir::RegFile file = ir::RegFile::Const; // Const, ConstInt or ConstBool
  uint32_t index = 0;
  Vec4 f{0, 0, 0, 0};
  std::array<int32_t, 4> i{};
  bool b = false;
};

// --input v#|t#=x,y,z,w (pixel stage) and --attr vN=x,y,z,w|quad-uv (vertex stage).
struct RegisterSetting {
  ir::RegFile file = ir::RegFile::Input; // Input (v#) or Texture (t#)
  uint32_t index = 0;
  Vec4 value{0, 0, 0, 1};
  bool quad_uv = false; // --attr only
};

// --texture sN=FILE.png|FILE.pfm|builtin:NAME[:WxH]
struct TextureSetting {
  TextureSetting() = default;
  TextureSetting(uint32_t s, std::string src, std::shared_ptr<const img::Image> im = nullptr)
      : sampler(s), source(std::move(src)), image(std::move(im)) {}
  uint32_t sampler = 0;
  std::string source;                      // file or builtin spec (img::load_texture)
  std::shared_ptr<const img::Image> image; // when set: this image, `source` only names it
};

struct ProbePoint {
  uint32_t x = 0, y = 0;
};

// Flag-value parsers: the value, or nullopt and a one-line reason in `error`.
std::optional<ConstSetting> parse_const_setting(std::string_view text, std::string& error);
std::optional<RegisterSetting> parse_input_setting(std::string_view text, std::string& error);
std::optional<RegisterSetting> parse_attr_setting(std::string_view text, std::string& error);
std::optional<TextureSetting> parse_texture_setting(std::string_view text, std::string& error);
std::optional<ProbePoint> parse_probe(std::string_view text, std::string& error);
// "WxH", 1..img::kMaxDimension each.
std::optional<std::array<uint32_t, 2>> parse_size(std::string_view text, std::string& error);
std::optional<Filter> parse_filter(std::string_view text);       // point|linear
std::optional<AddressMode> parse_address(std::string_view text); // clamp|wrap|mirror|border
std::optional<ir::PixelCenter> parse_pixel_center(std::string_view text); // d3d9|modern

struct RunRequest {
  std::shared_ptr<const ir::Program> vs, ps; // validated listings; either may be null
  uint32_t width = 256, height = 256;
  img::Format format = img::Format::RGBA8;
  std::vector<ConstSetting> constants;
  std::vector<RegisterSetting> inputs; // used only without a vertex program
  std::vector<RegisterSetting> attrs;  // used only with a vertex program
  std::vector<TextureSetting> textures;
  Filter filter = Filter::Point;
  AddressMode address = AddressMode::Wrap;
  ir::Conventions conventions;
  std::vector<ProbePoint> probes;
  unsigned threads = 0; // 0 = every core
};

struct ProbeValue {
  uint32_t x = 0, y = 0;
  Vec4 value{}; // as stored
};

// Problems, kept apart by where their positions point: into the vertex listing's
// SourceManager, the pixel listing's, or nowhere (flags, textures, the draw).
struct RunDiagnostics {
  ir::DiagnosticSink vs, ps, other;
  bool has_errors() const { return vs.has_errors() || ps.has_errors() || other.has_errors(); }
};
// Rule of the `other` error for a texture file that does not exist (an I/O problem, as
// opposed to a file that exists but does not decode).
inline constexpr std::string_view kRuleTextureMissing = "texture-missing";

struct RunResult {
  bool ok = false;
  img::Image image;
  std::vector<ProbeValue> probes;
  DrawStats stats;
  double setup_ms = 0, draw_ms = 0;
};

// Builds the pass (pass_from_request), draws it and reads the probes. ok is false on any
// error (reported in `diags`); warnings never stop the run.
RunResult run_job(const RunRequest& request, RunDiagnostics& diags);

// The pass run_job draws, for callers that want to draw it themselves (textures loaded):
// e.g. several passes summed into one target — set pass.blend = BlendMode::OneOne and
// call draw(pass, target) for each.
// nullopt after reporting errors to `diags`.
std::optional<Pass> pass_from_request(const RunRequest& request, RunDiagnostics& diags);

// Writes the image atomically: ".pfm" → PFM (float RGB), otherwise PNG, 8-bit for RGBA8
// targets and 16-bit for float targets. Empty string on success, else the reason. When a
// PNG must clamp values outside [0, 1] (or NaN), `warning` says so (use .pfm for HDR).
std::string write_run_output(const std::string& path, const img::Image& image,
                             std::string* warning = nullptr);

} // namespace tierlift::cpu
