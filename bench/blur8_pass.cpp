#include "blur8_pass.h"

#include <memory>
#include <string>

#include "tierlift/asm/parser.h"
#include "tierlift/cpu/run_job.h"
#include "tierlift/listings/embedded.h"

namespace tierlift::bench {
namespace {

std::shared_ptr<const ir::Program> listing(const char* name) {
  auto text = listings::find_embedded(std::string("gpugems21/") + name);
  auto r = as::parse_text(std::string(text.value_or("")), name);
  return r.program ? std::make_shared<const ir::Program>(std::move(*r.program)) : nullptr;
}

} // namespace

float blur8_offset(int k) {
  return (float(k) - 3.5f + 0.5f) / float(kBlurWidth);
}

std::optional<cpu::Pass> blur8_pass() {
  cpu::RunRequest r;
  r.vs = listing("listing1_blur8_coords.vsh");
  r.ps = listing("listing2_blur8_weighted_sum.psh");
  if (!r.vs || !r.ps) return std::nullopt;
  r.width = kBlurWidth;
  r.height = kBlurHeight;
  r.format = img::Format::RGBA8;
  std::string err;
  for (int k = 0; k < 8; ++k) {
    r.constants.push_back(*cpu::parse_const_setting(
        "vs:c" + std::to_string(k) + "=" + std::to_string(blur8_offset(k)) + ",0,0,0", err));
    r.constants.push_back(
        *cpu::parse_const_setting("ps:c" + std::to_string(k) + "=0.125,0.125,0.125,0.125", err));
  }
  r.attrs.push_back(*cpu::parse_attr_setting("v3=quad-uv", err));
  r.textures.push_back({0, "builtin:noise:1920x1080"});
  r.filter = cpu::Filter::Linear;
  r.address = cpu::AddressMode::Clamp;
  cpu::RunDiagnostics d;
  return cpu::pass_from_request(r, d);
}

} // namespace tierlift::bench
