// Helpers shared by the vertex and pixel evaluators, and the public extract_taps().
#include <algorithm>
#include <fmt/format.h>

#include "linear_forms.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/source_modifiers.h"

namespace tierlift::analytic {

namespace detail {

std::string where(const ir::SourceLoc& loc) {
  if (!loc.valid()) return "(no position)";
  return fmt::format("line {}:{}", loc.line, loc.col);
}

std::array<double, 4> constant_value(const ir::FoldedDefs& defs, const std::vector<Vec4>& api,
                                     uint32_t index, bool ps1x_clamp, bool* clamped) {
  std::array<double, 4> v{};
  if (index < api.size())
    for (int c = 0; c < 4; ++c) v[c] = api[index][c];
  if (const ir::ConstDef* d = defs.find(ir::RegFile::Const, index))
    for (int c = 0; c < 4; ++c) v[c] = d->f(c);
  if (ps1x_clamp)
    for (double& x : v) {
      double y = std::clamp(x, -1.0, 1.0);
      if (y != x && clamped) *clamped = true;
      x = y;
    }
  return v;
}

std::optional<AffineMod> affine_modifier(ir::SrcMod mod) {
  const ir::SrcModInfo& m = ir::src_mod_info(mod);
  if (!m.affine) return std::nullopt; // _dz, _dw, _abs, ! are not affine
  return AffineMod{m.scale, m.bias};
}

std::string place_taps(const CoordForms& coords, std::vector<Tap>& taps) {
  for (Tap& t : taps) {
    if (t.texcoord >= coords.coord.size() || !coords.coord[t.texcoord])
      return fmt::format("vertex listing: oT{} (sampled by the pixel listing) is not the "
                         "texcoord input times a scale plus a constant: {}",
                         t.texcoord,
                         t.texcoord < 8 ? coords.why_not[t.texcoord] : "no such register");
    t.offset = coords.coord[t.texcoord]->offset;
    t.scale = coords.coord[t.texcoord]->scale;
    t.corners = coords.coord[t.texcoord]->corner;
  }
  return "";
}

} // namespace detail

namespace detail {

std::string structural_error(std::string_view who, const ir::Program& vs, const ir::Program& ps) {
  if (!ir::is_vertex(vs.profile) || !ir::is_pixel(ps.profile))
    return fmt::format("{} needs a vertex listing and a pixel listing", who);
  if (ir::Status s = ir::validate_ir(vs); !s) return "vertex listing: " + s.message();
  if (ir::Status s = ir::validate_ir(ps); !s) return "pixel listing: " + s.message();
  for (const ir::Program* p : {&vs, &ps}) {
    if (ir::Status s = ir::check_executable(*p, "the analytic model"); !s) return s.message();
    // Its forms know the registers and instructions of shader models 1 and 2.0 only.
    if (ir::has_predication(p->profile))
      return fmt::format("the analytic model runs shader models 1 and 2.0, not {}",
                         ir::profile_name(p->profile));
  }
  return {};
}

ir::Failure form_failure(std::string message) {
  return ir::fail("analytic", std::string(kFormRule), std::move(message));
}

} // namespace detail

ir::Result<TapExtraction> extract_taps(const ir::Program& vs, const std::vector<Vec4>& vs_consts,
                                       const ir::Program& ps, const std::vector<Vec4>& ps_consts) {
  if (std::string e = detail::structural_error("extract_taps", vs, ps); !e.empty())
    return detail::form_failure(e);
  detail::CoordForms coords = detail::evaluate_coords(vs, vs_consts);
  if (!coords.error.empty()) return detail::form_failure("vertex listing: " + coords.error);
  detail::SumForm sum = detail::evaluate_sum(ps, ps_consts, coords.colour);
  if (!sum.error.empty()) return detail::form_failure("pixel listing: " + sum.error);
  if (std::string e = detail::place_taps(coords, sum.taps); !e.empty())
    return detail::form_failure(e);
  TapExtraction out;
  out.taps = std::move(sum.taps);
  out.notes = std::move(sum.notes);
  out.texcoord_input = coords.texcoord_input;
  return out;
}

} // namespace tierlift::analytic
