// generate_listing: the profile's sections in order, then the printed program.
#include <string>

#include "builder.h"
#include "tierlift/assembly/printer.h"
#include "tierlift/ir/profile.h"

namespace tierlift::gen {

bool generates(ir::Profile p) {
  switch (p) {
  case ir::Profile::vs_1_1:
  case ir::Profile::vs_2_0:
  case ir::Profile::vs_2_x:
  case ir::Profile::vs_3_0:
  case ir::Profile::ps_1_1:
  case ir::Profile::ps_1_2:
  case ir::Profile::ps_1_3:
  case ir::Profile::ps_1_4:
  case ir::Profile::ps_2_0:
  case ir::Profile::ps_2_x:
  case ir::Profile::ps_3_0: return true;
  }
  return false;
}

std::string generated_profile_names() {
  std::string out;
  for (ir::Profile p : ir::kAllProfiles)
    if (generates(p)) out += (out.empty() ? "" : ", ") + std::string(ir::profile_name(p));
  return out;
}

ir::Result<ir::Profile> generated_profile(std::string_view name) {
  const std::optional<ir::Profile> profile = ir::parse_profile(name);
  if (!profile)
    return ir::fail("--profile", "usage", "unknown profile '" + std::string(name) + "'");
  // A profile added to the front end is refused until the builder knows its shapes (output
  // rules, declarations): listings without them would not validate.
  if (!generates(*profile))
    return ir::fail("--profile", "usage",
                    "the generator does not write " + std::string(name) + " programs (it writes " +
                        generated_profile_names() + ")");
  return *profile;
}

ir::Result<std::string> generate_listing(std::string_view profile_name, std::uint64_t seed,
                                         std::size_t index, const GenerateOptions& options) {
  const ir::Result<ir::Profile> profile = generated_profile(profile_name);
  if (!profile) return profile.failure();
  // One stream per (profile, seed, index): listing k does not depend on listings before it.
  detail::Rng mix(seed ^ (0x9E3779B97F4A7C15ull * (index + 1)) ^
                  (std::uint64_t(ir::profile_index(*profile)) << 56));
  detail::Builder b(*profile, options, mix.next());
  const std::size_t lo = options.min_instructions;
  const std::size_t n =
      lo + b.rng.below(options.max_instructions >= lo ? options.max_instructions - lo + 1 : 1);
  switch (*profile) {
  case ir::Profile::ps_1_1:
  case ir::Profile::ps_1_2:
  case ir::Profile::ps_1_3:
    detail::texture_stages_ps11_13(b);
    detail::instruction_loop(b, n, false, true);
    break;
  case ir::Profile::ps_1_4:
    b.pending_phase = b.rng.chance(0.6);
    detail::texture_section_ps14(b, false);
    detail::instruction_loop(b, n / 2, false, true);
    if (b.pending_phase) {
      b.pending_phase = false;
      if (b.accept({detail::make(ir::Opcode::Phase, std::nullopt)}))
        detail::texture_section_ps14(b, true);
      else
        b.pending_phase = true; // the body is valid with the tail's marker only
    }
    detail::instruction_loop(b, n - n / 2, false, true);
    break;
  default: detail::instruction_loop(b, n, true, true); break;
  }
  return assembly::print_program(b.finish());
}

ir::Result<std::string> generate_listing(std::string_view profile, std::uint64_t seed,
                                         std::size_t index) {
  return generate_listing(profile, seed, index, GenerateOptions{});
}

} // namespace tierlift::gen
