#include "blur8_pass.h"

#include <memory>
#include <string>

#include "tierlift/assembly/parser.h"
#include <cstdlib>
#include <string>

#include "tierlift/listings/embedded.h"
#include "tierlift/pass/setup.h"

namespace tierlift::bench {
namespace {

std::shared_ptr<const ir::Program> listing(const char* name) {
  auto text = listings::find_embedded(std::string("gpugems21/") + name);
  auto r = assembly::parse_text(std::string(text.value_or("")), name);
  return r.program ? std::make_shared<const ir::Program>(std::move(*r.program)) : nullptr;
}

} // namespace

float blur8_offset(int k) {
  return (float(k) - 3.5f + 0.5f) / float(kBlurWidth);
}

std::optional<cpu::Pass> blur8_pass() {
  pass::RunRequest r;
  r.vs = listing("listing1_blur8_coords.vsh");
  r.ps = listing("listing2_blur8_weighted_sum.psh");
  if (!r.vs || !r.ps) return std::nullopt;
  r.width = kBlurWidth;
  r.height = kBlurHeight;
  r.format = img::Format::RGBA8;
  for (uint32_t k = 0; k < 8; ++k) {
    // Through six decimals, as the bench always passed it (a --const text).
    const float offset =
        std::strtof(std::to_string(blur8_offset(static_cast<int>(k))).c_str(), nullptr);
    r.constants.push_back(
        {pass::StageMask::Vertex, ir::RegFile::Const, k, {offset, 0, 0, 0}, {}, false});
    r.constants.push_back({pass::StageMask::Pixel,
                           ir::RegFile::Const,
                           k,
                           {0.125f, 0.125f, 0.125f, 0.125f},
                           {},
                           false});
  }
  r.attrs.push_back({ir::RegFile::Input, 3, {0, 0, 0, 1}, true}); // v3 = the quad uv
  r.textures.push_back({0, "builtin:noise:1920x1080"});
  r.filter = cpu::Filter::Linear;
  r.address = cpu::AddressMode::Clamp;
  ir::Result<pass::Pass> prepared = pass::prepare_pass(r);
  if (!prepared) return std::nullopt;
  return std::move(prepared).value();
}

void set_blur_rate(benchmark::State& state) {
  state.SetItemsProcessed(int64_t(state.iterations()) * kBlurWidth * kBlurHeight);
  state.counters["Mpix/s"] = benchmark::Counter(double(kBlurWidth) * kBlurHeight * 1e-6,
                                                benchmark::Counter::kIsIterationInvariantRate);
}

void time_interpreter(benchmark::State& state, unsigned threads) {
  auto pass = blur8_pass();
  if (!pass) {
    state.SkipWithError("could not build the pass");
    return;
  }
  img::Image target(kBlurWidth, kBlurHeight, img::Format::RGBA8);
  for (auto _ : state) {
    auto stats = cpu::draw(*pass, target, threads);
    benchmark::DoNotOptimize(stats);
  }
  set_blur_rate(state);
}

} // namespace tierlift::bench
