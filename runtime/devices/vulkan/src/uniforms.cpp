// Fills a stage's uniform block at the offsets of its layout (codegen::UniformBlockInfo, the
// one description the code generator declared the block from).
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
    for (uint32_t k = 0; k < 4; ++k) put(u.float_at(c, k), std::bit_cast<uint32_t>(bank.f[c][k]));
  for (const auto& [c, v] : module.block_defs) // a def wins over the bound constant
    if (c < u.float_count)
      for (uint32_t k = 0; k < 4; ++k) put(u.float_at(c, k), std::bit_cast<uint32_t>(v[k]));
  if (u.int_offset) {
    for (uint32_t n = 0; n < codegen::UniformBlockInfo::kIntRegisters; ++n)
      for (uint32_t k = 0; k < 4; ++k) put(u.int_at(n, k), static_cast<uint32_t>(bank.i[n][k]));
    for (uint32_t n = 0; n < codegen::UniformBlockInfo::kBoolRegisters; ++n)
      put(u.bool_at(n), bank.b[n] ? 1u : 0u);
  }
  if (u.bump_offset) {
    for (uint32_t s = 0; s < codegen::UniformBlockInfo::kBumpStages; ++s) {
      const pass::StageState& st = pass.textures[s].stage;
      for (uint32_t k = 0; k < 4; ++k)
        put(u.bump_matrix_at(s, k), std::bit_cast<uint32_t>(st.bumpenv_mat[k]));
      put(u.bump_lscale_at(s), std::bit_cast<uint32_t>(st.bumpenv_lscale));
      put(u.bump_loffset_at(s), std::bit_cast<uint32_t>(st.bumpenv_loffset));
    }
  }
  return words;
}

} // namespace tierlift::vulkan
