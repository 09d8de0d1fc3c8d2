// The object pass and the stencil test as math (analytic_stencil.h).
#include "analytic_stencil.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "tierlift/analytic/taps.h"
#include "tierlift/pass/stencil.h"

namespace tierlift::effects::detail {

std::string coverage(const PassDesc& pass, const ir::Conventions& conventions, uint32_t w,
                     uint32_t h, std::vector<uint8_t>& covered) {
  if (pass.draw.vertices.empty()) {
    covered.assign(size_t{w} * h, 1);
    return {};
  }
  covered.assign(size_t{w} * h, 0);
  if (ir::Status quad = analytic::check_position_passthrough(*pass.draw.vertex_program); !quad)
    return fmt::format("cannot model pass '{}': vertex listing: {}", pass.name, quad.message());
  const uint32_t reg = pass::position_input(*pass.draw.vertex_program);
  if (reg >= 16) return fmt::format("pass '{}': position input v{} out of range", pass.name, reg);
  // Screen positions: x_s = (x/w + 1)·W/2, y_s = (1 − y/w)·H/2 (docs/design.md), snapped to
  // 1/256 pixel as D3D9 and Vulkan rasterisers with 8 sub-pixel bits place vertices. The
  // snapped values have few bits, so the edge functions below are exact in double.
  auto snap = [](double v) { return std::nearbyint(v * 256.0) / 256.0; };
  std::vector<std::array<double, 2>> screen;
  for (const pass::VertexInput& v : pass.draw.vertices) {
    const pass::Vec4& p = v.v[reg];
    if (p[3] != 1.0f || p[2] < 0.0f || p[2] > 1.0f)
      return fmt::format("cannot model pass '{}': vertices must have w = 1 and 0 ≤ z ≤ 1",
                         pass.name);
    screen.push_back({snap((double{p[0]} + 1.0) * w / 2.0), snap((1.0 - double{p[1]}) * h / 2.0)});
  }
  std::vector<std::array<uint32_t, 3>> tris = pass.draw.triangles;
  if (tris.empty())
    for (uint32_t i = 0; i + 2 < screen.size(); i += 3) tris.push_back({i, i + 1, i + 2});
  const double offset = conventions.pixel_center == ir::PixelCenter::Modern ? 0.5 : 0.0;
  for (const auto& t : tris) {
    const auto& a = screen[t[0]];
    const auto& b = screen[t[1]];
    const auto& c = screen[t[2]];
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if (area == 0) continue;
    const double x0 = std::min({a[0], b[0], c[0]}), x1 = std::max({a[0], b[0], c[0]});
    const double y0 = std::min({a[1], b[1], c[1]}), y1 = std::max({a[1], b[1], c[1]});
    const int64_t i0 = std::max<int64_t>(0, static_cast<int64_t>(std::floor(x0 - offset)));
    const int64_t i1 = std::min<int64_t>(w - 1, static_cast<int64_t>(std::ceil(x1 - offset)));
    const int64_t j0 = std::max<int64_t>(0, static_cast<int64_t>(std::floor(y0 - offset)));
    const int64_t j1 = std::min<int64_t>(h - 1, static_cast<int64_t>(std::ceil(y1 - offset)));
    for (int64_t j = j0; j <= j1; ++j)
      for (int64_t i = i0; i <= i1; ++i) {
        const double px = static_cast<double>(i) + offset, py = static_cast<double>(j) + offset;
        auto edge = [&](const std::array<double, 2>& p, const std::array<double, 2>& q) {
          return ((q[0] - p[0]) * (py - p[1]) - (q[1] - p[1]) * (px - p[0])) * area;
        };
        const double e0 = edge(b, c), e1 = edge(c, a), e2 = edge(a, b);
        if (e0 == 0 || e1 == 0 || e2 == 0) {
          if ((e0 >= 0 && e1 >= 0 && e2 >= 0))
            return fmt::format("cannot model pass '{}': pixel ({}, {})'s sample point lies on "
                               "an edge of the object (the fill rule decides it)",
                               pass.name, i, j);
          continue;
        }
        if (e0 > 0 && e1 > 0 && e2 > 0) covered[size_t(j) * w + size_t(i)] = 1;
      }
  }
  return {};
}

std::string constant_outputs(const PassDesc& pass, std::array<pass::Vec4, 4>& out,
                             uint8_t& written) {
  written = 0;
  auto refuse = [&](const ir::Instruction& in) {
    return fmt::format("cannot model pass '{}' as constant outputs: line {}: only "
                       "`mov oC#, c#` is modelled",
                       pass.name, in.loc.line);
  };
  for (const ir::Instruction& in : pass.draw.pixel_program->code) {
    if (in.op != ir::Opcode::Mov || !in.dst || in.src.size() != 1) return refuse(in);
    const ir::DstOperand& d = *in.dst;
    const ir::SrcOperand& s = in.src[0];
    if (d.file != ir::RegFile::ColorOut || d.index >= 4 || d.mask != ir::kFullMask ||
        s.file != ir::RegFile::Const || s.rel || s.swizzle != ir::kIdentitySwizzle ||
        s.mod != ir::SrcMod::None || in.mods.sat || in.mods.shift != 0)
      return refuse(in);
    bool found = false;
    for (const ir::ConstDef& def : pass.draw.pixel_program->defs)
      if (def.file == ir::RegFile::Const && def.index == s.index) {
        for (int c = 0; c < 4; ++c) out[d.index][size_t(c)] = def.f(c);
        found = true;
      }
    if (!found) {
      if (s.index < pass.draw.ps_constants.f.size())
        out[d.index] = pass.draw.ps_constants.f[s.index];
      else
        out[d.index] = {0, 0, 0, 0}; // an unset constant reads zero (D3D9's reset state)
    }
    written |= static_cast<uint8_t>(1u << d.index);
  }
  return {};
}

void apply_stencil(const PassDesc& pass, img::Image& stencil, std::vector<uint8_t>& covered) {
  const pass::DepthStencilState& ds = pass.draw.depth_stencil;
  if (!ds.stencil_test) return;
  for (size_t i = 0; i < covered.size(); ++i) {
    if (!covered[i]) continue;
    float& r = stencil.rgba[4 * i];
    const auto stored = static_cast<uint8_t>(r);
    const bool passed = pass::stencil_test(ds, stored);
    r = pass::stencil_update(passed ? ds.stencil_pass : ds.stencil_fail, ds, stored);
    if (!passed) covered[i] = 0;
  }
}

} // namespace tierlift::effects::detail
