// Fills a stage's uniform block exactly as emit_module.cpp laid it out (std140): c# at
// 16·#, i# and b# (vs_2_0) and the bump-environment states (ps_1_x) after the floats.
#include "tierlift/vulkan/uniforms.h"

#include <bit>

namespace tierlift::vulkan {

std::vector<uint32_t> pack_uniforms(const codegen::ShaderModule& module,
                                    const pass::ConstantBank& bank, const pass::Pass& pass) {
  const codegen::UniformBlockInfo& u = module.uniforms;
  std::vector<uint32_t> words(u.size_bytes / 4, 0);
  if (words.empty()) return words;
  auto put = [&](uint32_t byte_offset, uint32_t word) {
    const size_t at = byte_offset / 4;
    if (at < words.size()) words[at] = word;
  };
  for (uint32_t c = 0; c < u.float_count && c < bank.f.size(); ++c)
    for (uint32_t k = 0; k < 4; ++k) put(16 * c + 4 * k, std::bit_cast<uint32_t>(bank.f[c][k]));
  if (u.int_offset) {
    for (uint32_t n = 0; n < 16; ++n) {
      for (uint32_t k = 0; k < 4; ++k)
        put(u.int_offset + 16 * n + 4 * k, static_cast<uint32_t>(bank.i[n][k]));
      put(u.bool_offset + 16 * n, bank.b[n] ? 1u : 0u);
    }
  }
  if (u.bump_offset) {
    for (uint32_t s = 0; s < 8; ++s) {
      const pass::StageState& st = pass.textures[s].stage;
      for (uint32_t k = 0; k < 4; ++k)
        put(u.bump_offset + 32 * s + 4 * k, std::bit_cast<uint32_t>(st.bumpenv_mat[k]));
      put(u.bump_offset + 32 * s + 16, std::bit_cast<uint32_t>(st.bumpenv_lscale));
      put(u.bump_offset + 32 * s + 20, std::bit_cast<uint32_t>(st.bumpenv_loffset));
    }
  }
  return words;
}

} // namespace tierlift::vulkan
