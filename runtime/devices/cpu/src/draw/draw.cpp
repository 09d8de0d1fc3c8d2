// One pass: vertex stage, setup, then rows of pixels shaded and stored by worker threads.
#include "tierlift/cpu/draw.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <fmt/format.h>
#include <mutex>
#include <thread>

#include "raster.h"
#include "tierlift/ir/sm3_interface.h"
#include "tierlift/pass/depth.h"
#include "tierlift/pass/srgb.h"
#include "tierlift/pass/stencil.h"
#include "tierlift/rounding/rounding.h"
#include "worker_pool.h"

namespace tierlift::cpu {
namespace {

using detail::PixelRect;
using detail::RasterJob;
using detail::Triangle;
using detail::WorkerStats;

constexpr int64_t kBandRows = 4;     // rows a worker takes at a time
constexpr int64_t kMaxWorkers = 256; // --threads 100000 must not start 100000 threads

struct PassPrograms {
  std::optional<ShaderVM> vs, ps;
};

void store_pixel(const RasterJob& job, img::Image& target, const Vec4& shaded, int64_t x,
                 int64_t y) {
  float* px = target.at(static_cast<uint32_t>(x), static_cast<uint32_t>(y));
  // D3DRS_SRGBWRITEENABLE: R, G, B encoded before the blender (NUMERICS.md S3).
  Vec4 color = shaded;
  if (job.pass.srgb_write && target.format == img::Format::RGBA8)
    for (int c = 0; c < 3; ++c) color[c] = rounding::srgb_encoded(color[c]);
  Vec4 stored = blend_and_store(job.pass.blend, target.format, color, {px[0], px[1], px[2], px[3]},
                                job.pass.conventions.rounding);
  std::copy(stored.begin(), stored.end(), px);
}

void shade_pixel(const RasterJob& job, const PixelInput& in, int64_t x, int64_t y,
                 WorkerStats& stats) {
  PixelOutput out;
  out.color[0] = in.color[0];
  ++stats.shaded;
  if (job.ps) {
    out = job.ps->run_pixel(in, job.pass.ps_constants, job.textures);
    if (out.discarded) {
      ++stats.killed;
      return;
    }
  }
  detail::store_shaded(job, out, in.depth, x, y);
}

void raster_rows(const RasterJob& job, int64_t y0, int64_t y1, WorkerStats& stats) {
  PixelInput constant = job.pass.constant_inputs;
  for (auto& c : constant.color)
    for (auto& v : c) v = detail::clamp01(v);
  for (const Triangle& t : job.triangles) {
    int64_t ya = std::max(y0, t.bounds.y0), yb = std::min(y1, t.bounds.y1);
    for (int64_t y = ya; y < yb; ++y) {
      int64_t py = y * detail::kSubPixelOne + job.sample_offset;
      for (int64_t x = t.bounds.x0; x < t.bounds.x1; ++x) {
        int64_t px = x * detail::kSubPixelOne + job.sample_offset;
        int64_t e[3];
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) {
          e[k] = detail::edge(t.v[(k + 1) % 3], t.v[(k + 2) % 3], px, py);
          inside = e[k] > 0 || (e[k] == 0 && t.top_left[k]);
        }
        if (!inside) continue;
        PixelInput in = job.constant_inputs ? constant : detail::interpolate(t, e, x, y);
        detail::set_position_and_face(in, t, x, y);
        shade_pixel(job, in, x, y, stats);
      }
    }
  }
}

} // namespace

void detail::store_shaded(const RasterJob& job, const PixelOutput& out, float interpolated_z,
                          int64_t x, int64_t y) {
  const pass::DepthStencilState& ds = job.pass.depth_stencil;
  const size_t at = static_cast<size_t>(y) * job.target.width + static_cast<size_t>(x);
  if (ds.stencil_test) {
    uint8_t& s = job.targets.stencil[at];
    const bool passed = pass::stencil_test(ds, s);
    s = pass::stencil_update(passed ? ds.stencil_pass : ds.stencil_fail, ds, s);
    if (!passed) return;
  }
  if (ds.depth_test) { // ZENABLE; without it ZWRITEENABLE writes nothing (pass/depth.h)
    const float z = pass::fragment_depth(out.depth ? &*out.depth : nullptr, interpolated_z,
                                         job.pass.conventions.rounding == ir::Rounding::Llvmpipe);
    float& stored = job.targets.depth[at];
    if (!pass::depth_passes(ds.depth_func, z, stored)) return;
    if (ds.depth_write) stored = z;
  }
  for (uint32_t i = 0; i < job.pass.color_targets; ++i)
    store_pixel(job, *job.targets.color[i], out.color[i], x, y);
}

namespace {

std::string check_targets(const Pass& pass, const DrawTargets& targets) {
  if (pass.color_targets == 0 || pass.color_targets > targets.color.size())
    return "a pass draws into 1 to 4 render targets";
  const img::Image* first = targets.color[0];
  for (uint32_t i = 0; i < pass.color_targets; ++i) {
    const img::Image* t = targets.color[i];
    if (!t) return fmt::format("render target {} (oC{}) is not bound", i, i);
    if (t->width != first->width || t->height != first->height)
      return fmt::format("render target {} is {}x{}, render target 0 is {}x{}: every target of "
                         "a pass has one size",
                         i, t->width, t->height, first->width, first->height);
    for (uint32_t j = 0; j < i; ++j)
      if (targets.color[j] == t) return fmt::format("render targets {} and {} are one image", j, i);
  }
  if (pass::uses_depth(pass.depth_stencil) && !targets.depth)
    return "the pass has a depth state but no depth buffer is bound";
  if (pass::uses_depth(pass.depth_stencil) && pass.depth_stencil.stencil_test)
    return "a depth buffer and a stencil buffer in one pass are not drawn yet";
  if (pass.depth_stencil.stencil_test && !targets.stencil)
    return "the pass has a stencil test but no stencil buffer is bound";
  return {};
}

std::string check_inputs(const Pass& pass, const img::Image& target, const Viewport& vp) {
  if (target.width > img::kMaxDimension || target.height > img::kMaxDimension)
    return "render target larger than 16384x16384";
  if (target.rgba.size() != size_t{target.width} * target.height * 4)
    return "render target pixel buffer does not match its size";
  constexpr int32_t kMax = static_cast<int32_t>(img::kMaxDimension);
  if (vp.x < -kMax || vp.x > kMax || vp.y < -kMax || vp.y > kMax || vp.width > img::kMaxDimension ||
      vp.height > img::kMaxDimension)
    return "viewport outside the supported range";
  if (pass.vertex_program && pass.vertex_program->stage() != ir::ShaderStage::Vertex)
    return "the vertex program is not a vertex shader";
  if (pass.pixel_program && pass.pixel_program->stage() != ir::ShaderStage::Pixel)
    return "the pixel program is not a pixel shader";
  if (pass.vertex_program && pass.vertices.empty())
    return "a vertex program needs vertices (see set_full_screen_quad)";
  if (ir::Status s = pass::check_supported(pass, kCapabilities, "cpu"); !s) return s.message();
  return {};
}

// DrawTargets::stale: whether the draw stores every pixel of the target whatever the stored
// values are, so that the leftovers need not be zeroed first.
bool overwrites_all(const Pass& pass, const std::vector<Triangle>& setup, const PixelRect& scissor,
                    const img::Image& target, int64_t sample_offset) {
  if (pass.color_targets != 1 || pass.blend != BlendMode::Replace ||
      pass.depth_stencil.stencil_test || pass.depth_stencil.depth_test)
    return false;
  if (pass.pixel_program)
    for (const ir::Instruction& ins : pass.pixel_program->code)
      if (ins.op == ir::Opcode::TexKill) return false;
  const PixelRect whole{0, 0, target.width, target.height};
  if (scissor.x0 != whole.x0 || scissor.y0 != whole.y0 || scissor.x1 != whole.x1 ||
      scissor.y1 != whole.y1)
    return false;
  return detail::covers(setup, whole, sample_offset);
}

ir::Failure draw_failure(std::string why) {
  return ir::fail("", std::string(kDrawRule), std::move(why));
}

void zero_targets(const Pass& pass, const DrawTargets& targets) {
  for (uint32_t i = 0; i < pass.color_targets; ++i)
    std::fill(targets.color[i]->rgba.begin(), targets.color[i]->rgba.end(), 0.0f);
}

} // namespace

ir::Result<DrawStats> draw(const Pass& pass, img::Image& target, unsigned threads) {
  DrawTargets targets;
  targets.color[0] = &target;
  return draw(pass, targets, threads);
}

namespace {

// The draw of a pass whose textures read as they are stored (no sRGB stage left).
ir::Result<DrawStats> draw_linear(const Pass& pass, const DrawTargets& targets, unsigned threads) {
  DrawStats stats;
  if (std::string why = targets.color[0] ? check_targets(pass, targets) : "no render target";
      !why.empty())
    return draw_failure(std::move(why));
  img::Image& target = *targets.color[0];
  // The block executor stores oC0 into one target and knows no depth, no stencil and no sRGB
  // write.
  const bool per_pixel_only =
      pass.color_targets > 1 || pass.depth_stencil.enabled() || pass.srgb_write;
  Viewport vp = pass.viewport;
  if (vp.width == 0) vp.width = target.width;
  if (vp.height == 0) vp.height = target.height;
  if (std::string why = check_inputs(pass, target, vp); !why.empty())
    return draw_failure(std::move(why));

  PassPrograms vms;
  const std::optional<ir::Program> fed = pass::fed_vertex_program(pass);
  const ir::Program* vertex_program = fed ? &*fed : pass.vertex_program.get();
  for (const auto& [program, vm] :
       {std::pair{vertex_program, &vms.vs}, std::pair{pass.pixel_program.get(), &vms.ps}}) {
    if (!program) continue;
    ir::Result<ShaderVM> made = ShaderVM::create(*program, pass.conventions);
    if (!made) return draw_failure("the shader VM refused the program: " + made.message());
    vm->emplace(std::move(*made));
  }
  // A mip chain read by lod: the reads meet in 2x2 quads, which the block executor has not.
  const bool lod_quads = tierlift::pass::reads_mips_by_lod(pass);
  if (lod_quads && vms.ps) vms.ps->enable_lod_quads();
  std::unique_ptr<PixelBlockVM> block; // null: the per-pixel VM runs the pixel stage
  try { // out of memory while planning the block executor: an error, not a crash
    if (pass.pixel_program && pass.executor == Executor::Auto && !per_pixel_only && !lod_quads)
      block = PixelBlockVM::create(*pass.pixel_program, pass.conventions, pass.ps_constants,
                                   /*coords_2d=*/true); // BoundTextures reads u, v only
  } catch (const std::exception& e) {
    return draw_failure(std::string("the shader VM refused the program: ") + e.what());
  }

  detail::PassSetup ps;
  if (std::string why = detail::setup_pass(pass, vms.vs ? &*vms.vs : nullptr, vp, target.width,
                                           target.height, ps);
      !why.empty())
    return draw_failure(std::move(why));
  const std::vector<Triangle>& setup = ps.triangles;
  const PixelRect& scissor = ps.scissor;
  const int64_t offset = ps.sample_offset;
  const bool constant_inputs = ps.constant_inputs;
  stats.triangles = setup.size();
  if (setup.empty() || scissor.x0 >= scissor.x1 || scissor.y0 >= scissor.y1) {
    if (targets.stale) zero_targets(pass, targets);
    return stats;
  }

  // Pixels: bands of rows handed out by an atomic counter. Which worker takes a band does
  // not change any pixel, since a pixel's whole history lives in one band.
  RasterJob job{pass,
                setup,
                vms.ps ? &*vms.ps : nullptr,
                block.get(),
                constant_inputs,
                offset,
                scissor,
                target,
                BoundTextures(pass.textures, pass.conventions.subtexel_bits,
                              pass.conventions.rounding == ir::Rounding::Llvmpipe),
                targets};
  // A program that reads its neighbours is shaded by 2x2 quads (raster_quads), which lie on
  // even rows: its bands start on one, so that no quad straddles two bands.
  const bool quads = job.ps && !job.block && job.ps->needs_quad();
  const int64_t band0 = quads ? scissor.y0 & ~int64_t{1} : scissor.y0;
  const int64_t bands = (scissor.y1 - band0 + kBandRows - 1) / kBandRows;
  unsigned workers = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
  workers = static_cast<unsigned>(std::min<int64_t>({workers, bands, kMaxWorkers}));
  // Each worker's block state is allocated here, before any pixel is written: once the
  // workers run nothing allocates or throws, so a draw fails only before it touches the target.
  std::vector<std::unique_ptr<detail::BlockWorker>> block_workers(workers);
  try {
    if (job.block)
      for (auto& bw : block_workers) bw = std::make_unique<detail::BlockWorker>(*job.block, job);
  } catch (const std::exception& e) {
    return draw_failure(std::string("draw failed: ") + e.what());
  }
  if (targets.stale && !overwrites_all(pass, setup, scissor, target, offset))
    zero_targets(pass, targets);
  std::atomic<int64_t> next{0};
  std::mutex mutex;
  std::string failure;
  auto work = [&](unsigned index, WorkerStats& ws) {
    try {
      detail::BlockWorker* bw = block_workers[index].get();
      for (int64_t b = next++; b < bands; b = next++) {
        int64_t y0 = band0 + b * kBandRows;
        const int64_t y1 = std::min(scissor.y1, y0 + kBandRows);
        if (bw)
          detail::raster_rows_block(job, y0, y1, *bw, ws);
        else if (quads)
          detail::raster_quads(job, y0, y1, ws);
        else
          raster_rows(job, y0, y1, ws);
      }
    } catch (const std::exception& e) { // never let an exception cross a thread boundary
      std::lock_guard lock(mutex);
      failure = e.what();
      next = bands;
    }
  };
  std::vector<WorkerStats> per(workers);
  // This thread is worker 0. A worker that cannot be started leaves its bands to the others
  // (the counter hands out whatever is left).
  detail::WorkerPool::shared().run(workers, [&](unsigned i) { work(i, per[i]); });
  for (const auto& w : per) {
    stats.pixels_shaded += w.shaded;
    stats.pixels_killed += w.killed;
    stats.pixels_block += w.block;
  }
  if (!failure.empty()) return draw_failure("draw failed: " + failure);
  return stats;
}

} // namespace

ir::Result<DrawStats> draw(const Pass& pass, const DrawTargets& targets, unsigned threads) {
  if (!pass::reads_srgb(pass)) return draw_linear(pass, targets, threads);
  // sRGB stages read their texels decoded before filtering (NUMERICS.md S1, S2): the pass
  // drawn with those images decoded once.
  Pass decoded = pass;
  for (pass::TextureBinding& b : decoded.textures) b = pass::srgb_resolved(b);
  return draw_linear(decoded, targets, threads);
}

// The vertex stage and setup of a pass, shared with trace_pixel (raster.h).
std::string detail::setup_pass(const Pass& pass, const ShaderVM* vs, const Viewport& vp,
                               uint32_t width, uint32_t height, PassSetup& out) {
  // Vertex stage.
  std::vector<VertexOutput> outs;
  std::vector<std::array<uint32_t, 3>> tris = pass.triangles;
  const bool constant_inputs = out.constant_inputs = !vs && pass.transformed.empty();
  if (vs) {
    outs.reserve(pass.vertices.size());
    // vs_3_0 texldl reads the vertex stage's own samplers with the pixel stage's sampling
    // rules (NUMERICS.md F14); sRGB ones decoded as the draw decodes the pixel stage's.
    std::array<pass::TextureBinding, pass::kMaxVertexSamplers> bindings;
    for (uint32_t s = 0; s < bindings.size(); ++s)
      bindings[s] = pass::srgb_resolved(pass.vertex_textures[s]);
    const BoundTextures textures(bindings, pass.conventions.subtexel_bits,
                                 pass.conventions.rounding == ir::Rounding::Llvmpipe);
    for (const VertexInput& v : pass.vertices)
      outs.push_back(vs->run_vertex(v, pass.vs_constants, textures));
  } else if (!constant_inputs) {
    outs = pass.transformed;
  } else {
    for (const Vec4& c : kQuadCorners) outs.emplace_back().pos = c;
    tris.assign(kQuadTriangles.begin(), kQuadTriangles.end());
  }
  if (tris.empty())
    for (uint32_t i = 0; i + 2 < outs.size(); i += 3) tris.push_back({i, i + 1, i + 2});

  // Setup.
  out.sample_offset = detail::sample_offset(pass.conventions);
  PixelRect& scissor = out.scissor;
  scissor = PixelRect{std::max<int64_t>(0, vp.x), std::max<int64_t>(0, vp.y),
                      std::min<int64_t>(width, int64_t{vp.x} + vp.width),
                      std::min<int64_t>(height, int64_t{vp.y} + vp.height)};
  if (pass.scissor) {
    scissor.x0 = std::max<int64_t>(scissor.x0, pass.scissor->x0);
    scissor.y0 = std::max<int64_t>(scissor.y0, pass.scissor->y0);
    scissor.x1 = std::min<int64_t>(scissor.x1, pass.scissor->x1);
    scissor.y1 = std::min<int64_t>(scissor.y1, pass.scissor->y1);
  }
  std::vector<Triangle>& setup = out.triangles;
  detail::ColorClamps clamps;
  if (pass.vertex_program && pass.pixel_program)
    clamps.vertex_out =
        ir::saturates_vertex_colors(pass.vertex_program->profile, pass.pixel_program->profile);
  if (pass.pixel_program) clamps.pixel_in = ir::saturates_colors(pass.pixel_program->profile);
  for (const auto& t : tris) {
    if (t[0] >= outs.size() || t[1] >= outs.size() || t[2] >= outs.size())
      return "triangle index out of range";
    detail::setup_triangle({&outs[t[0]], &outs[t[1]], &outs[t[2]]}, vp, scissor, pass.conventions,
                           clamps, setup);
  }
  // setup_triangle calls the clockwise winding front; a counter-clockwise front swaps them.
  if (pass.front_face == tierlift::pass::FrontFace::CounterClockwise)
    for (Triangle& t : setup) t.front = !t.front;
  return {};
}

} // namespace tierlift::cpu
