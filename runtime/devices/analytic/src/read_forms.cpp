// The texture reads of a pixel listing, placed by the vertex listing's coordinate forms,
// for passes whose output is not a weighted sum (the analytic device's rgb × alpha form).
#include <algorithm>

#include "linear_forms.h"

namespace tierlift::analytic {

ir::Result<std::vector<Tap>>
extract_reads(const ir::Program& vs, const std::vector<Vec4>& vs_consts, const ir::Program& ps) {
  if (std::string e = detail::structural_error("extract_reads", vs, ps); !e.empty())
    return detail::form_failure(e);
  detail::CoordForms coords = detail::evaluate_coords(vs, vs_consts);
  if (!coords.error.empty()) return detail::form_failure("vertex listing: " + coords.error);
  std::vector<Tap> reads;
  for (const ir::Instruction& in : ps.code) {
    ir::Result<std::optional<std::pair<uint32_t, uint32_t>>> sampled = detail::sample_key(in);
    if (!sampled) return detail::form_failure("pixel listing: " + sampled.message());
    const std::optional<std::pair<uint32_t, uint32_t>> key = *sampled;
    if (!key) continue;
    auto same = [&](const Tap& t) { return t.texcoord == key->first && t.sampler == key->second; };
    if (std::none_of(reads.begin(), reads.end(), same)) {
      Tap t;
      t.texcoord = key->first;
      t.sampler = key->second;
      reads.push_back(t);
    }
  }
  if (std::string e = detail::place_taps(coords, reads); !e.empty()) return detail::form_failure(e);
  return reads;
}

} // namespace tierlift::analytic
