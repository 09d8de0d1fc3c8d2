// The glow fog's constants as the fogged extract listing sees them (linear_pass.h, FogForm):
// read off the listing's own defs and the API-set constants, not from the scene's fog.
#include "linear_forms.h"
#include "tierlift/analytic/linear_pass.h"
#include "tierlift/ir/passes.h"

namespace tierlift::analytic {

FogForm fog_form(const ir::Program& ps, const std::vector<Vec4>& ps_consts) {
  const ir::FoldedDefs defs = ir::fold_defs(ps);
  const bool ps1x = ir::is_ps1x(ps.profile);
  FogForm f;
  f.slope = detail::constant_value(defs, ps_consts, 0, ps1x, nullptr);
  f.bias = detail::constant_value(defs, ps_consts, 1, ps1x, nullptr);
  f.color = detail::constant_value(defs, ps_consts, 2, ps1x, nullptr);
  f.scale = ps1x ? 4 : 1;
  return f;
}

} // namespace tierlift::analytic
