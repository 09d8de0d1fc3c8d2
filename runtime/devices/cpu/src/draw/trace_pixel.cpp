// trace_pixel: one pixel of a draw, its pixel program traced instruction by instruction. The
// geometry goes through the draw's own vertex stage and setup (setup_pass), the pixel's
// coverage through the raster loop's edge test and its inputs through the same
// interpolation, so the traced invocation is the one the draw ran there.
#include <algorithm>
#include <array>
#include <fmt/format.h>

#include "raster.h"
#include "tierlift/pass/srgb.h"

namespace tierlift::cpu {
namespace {

ir::Failure trace_failure(std::string why) {
  return ir::fail("", std::string(kDrawRule), std::move(why));
}

// Whether pixel (x, y) lies inside `t` (raster_rows' test, top-left rule included); its
// edge functions into e (all three, inside or not).
bool covers_pixel(const detail::Triangle& t, int64_t x, int64_t y, int64_t offset, int64_t e[3]) {
  const int64_t px = x * detail::kSubPixelOne + offset, py = y * detail::kSubPixelOne + offset;
  bool inside = true;
  for (int k = 0; k < 3; ++k) {
    e[k] = detail::edge(t.v[(k + 1) % 3], t.v[(k + 2) % 3], px, py);
    inside = inside && (e[k] > 0 || (e[k] == 0 && t.top_left[k]));
  }
  return inside;
}

} // namespace

ir::Result<PixelTrace> trace_pixel(const Pass& pass, uint32_t width, uint32_t height, uint32_t x,
                                   uint32_t y) {
  if (!pass.pixel_program) return trace_failure("the pass has no pixel program to trace");
  if (pass.pixel_program->stage() != ir::ShaderStage::Pixel)
    return trace_failure("the pixel program is not a pixel shader");
  if (pass.vertex_program && pass.vertex_program->stage() != ir::ShaderStage::Vertex)
    return trace_failure("the vertex program is not a vertex shader");
  if (x >= width || y >= height)
    return trace_failure(
        fmt::format("pixel {},{} lies outside the {}x{} target", x, y, width, height));
  std::optional<ShaderVM> vs;
  if (pass.vertex_program) {
    const std::optional<ir::Program> fed = pass::fed_vertex_program(pass);
    ir::Result<ShaderVM> made =
        ShaderVM::create(fed ? *fed : *pass.vertex_program, pass.conventions);
    if (!made) return trace_failure("the shader VM refused the program: " + made.message());
    vs.emplace(std::move(*made));
  }
  ir::Result<ShaderVM> ps = ShaderVM::create(*pass.pixel_program, pass.conventions);
  if (!ps) return trace_failure("the shader VM refused the program: " + ps.message());
  if (tierlift::pass::reads_mips_by_lod(pass)) ps->enable_lod_quads();

  Viewport vp = pass.viewport;
  if (vp.width == 0) vp.width = width;
  if (vp.height == 0) vp.height = height;
  detail::PassSetup setup;
  if (std::string why = detail::setup_pass(pass, vs ? &*vs : nullptr, vp, width, height, setup);
      !why.empty())
    return trace_failure(std::move(why));

  PixelTrace out;
  const int64_t px = x, py = y;
  const detail::PixelRect& r = setup.scissor;
  if (px < r.x0 || px >= r.x1 || py < r.y0 || py >= r.y1) return out;
  // The last covering triangle is the one whose result a Replace draw leaves in the pixel.
  const detail::Triangle* last = nullptr;
  int64_t e[3]{};
  for (const detail::Triangle& t : setup.triangles) {
    if (px < t.bounds.x0 || px >= t.bounds.x1 || py < t.bounds.y0 || py >= t.bounds.y1) continue;
    if (!covers_pixel(t, px, py, setup.sample_offset, e)) continue;
    last = &t;
  }
  if (!last) return out;
  // The inputs of pixel (qx, qy) of the triangle, inside it or not (a helper pixel's).
  auto input_at = [&](int64_t qx, int64_t qy) {
    PixelInput in;
    if (setup.constant_inputs) {
      in = pass.constant_inputs;
      for (auto& c : in.color)
        for (auto& v : c) v = detail::clamp01(v);
    } else {
      int64_t qe[3];
      covers_pixel(*last, qx, qy, setup.sample_offset, qe);
      in = detail::interpolate(*last, qe, qx, qy);
    }
    detail::set_position_and_face(in, *last, qx, qy);
    return in;
  };
  std::array<pass::TextureBinding, pass::kMaxSamplers> bindings = pass.textures;
  for (pass::TextureBinding& b : bindings) b = pass::srgb_resolved(b); // as draw reads them
  const BoundTextures textures(bindings, pass.conventions.subtexel_bits,
                               pass.conventions.rounding == ir::Rounding::Llvmpipe);
  out.covered = true;
  if (!ps->needs_quad()) {
    out.output = ps->run_pixel(input_at(px, py), pass.ps_constants, textures, out.trace);
    return out;
  }
  // Gradients: the pixel's whole quad runs, as in the draw (raster_quads.cpp).
  std::array<PixelInput, 4> in;
  for (int64_t l = 0; l < 4; ++l) in[size_t(l)] = input_at((px & ~1) + (l & 1), (py & ~1) + l / 2);
  std::array<PixelOutput, 4> quad_out;
  const int lane = static_cast<int>((py & 1) * 2 + (px & 1));
  ps->run_quad(in, pass.ps_constants, textures, quad_out, out.trace, lane);
  out.output = quad_out[size_t(lane)];
  return out;
}

} // namespace tierlift::cpu
