// A test aid of the differential harness (diff_harness.h), kept out of the product: the pixel
// program of a pass as SPIR-V, compiled as the Vulkan device compiles it, with every Input
// variable decorated Flat. Given to the device as Pass::pixel_spirv (the module the device
// compiles itself describes the same interface), a varying is then the provoking vertex's
// value bit for bit. Only meaningful when all vertices of a primitive carry the same outputs
// (then the CPU device's interpolation also returns that value); it keeps ±inf varyings from
// turning into NaN in the rasteriser's attribute gradients.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "tierlift/codegen/codegen.h"
#include "tierlift/pass/pass.h"

namespace tierlift::vulkan::test {

// `words` with an OpDecorate Flat for every Input variable, put where annotations belong
// (before the first type, constant or variable); `words` unchanged when it is not a module.
inline std::vector<uint32_t> decorate_inputs_flat(const std::vector<uint32_t>& words) {
  if (words.size() < 5) return words; // the header is 5 words
  std::vector<uint32_t> inputs;
  size_t insert_at = 0;
  for (size_t i = 5; i < words.size();) {
    uint32_t count = words[i] >> 16, op = words[i] & 0xFFFFu;
    if (count == 0 || i + count > words.size()) return words;
    if (op == 59 /* OpVariable */ && count >= 4 && words[i + 3] == 1 /* Input */)
      inputs.push_back(words[i + 2]);
    if (insert_at == 0 && op >= 19 /* OpTypeVoid */ && op <= 59 /* OpVariable */) insert_at = i;
    i += count;
  }
  if (insert_at == 0) return words;
  std::vector<uint32_t> out(words.begin(), words.begin() + static_cast<long>(insert_at));
  for (uint32_t id : inputs) {
    out.push_back((3u << 16) | 71u /* OpDecorate */);
    out.push_back(id);
    out.push_back(14u /* Flat */);
  }
  out.insert(out.end(), words.begin() + static_cast<long>(insert_at), words.end());
  return out;
}

// The pass's pixel program with flat inputs, compiled with the options the Vulkan device
// derives from the pass (conventions, projected stages); nullptr when it does not compile.
inline std::shared_ptr<const std::vector<uint32_t>> flat_pixel_spirv(const pass::Pass& pass) {
  codegen::CodegenOptions co;
  co.conventions = pass.conventions;
  for (uint32_t s = 0; s < pass::kMaxSamplers; ++s)
    co.stage_projected[s] = pass.textures[s].stage.projected;
  ir::DiagnosticSink diags;
  auto pair = codegen::compile_pair(*pass.vertex_program, *pass.pixel_program, co, diags);
  if (!pair) return nullptr;
  return std::make_shared<const std::vector<uint32_t>>(decorate_inputs_flat(pair->ps.words));
}

} // namespace tierlift::vulkan::test
