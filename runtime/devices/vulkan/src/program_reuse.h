// Internal: what a TextureSet with program reuse on (TextureSet::set_reuse_programs) keeps
// from one draw to the next, clear() included: the compiled SPIR-V of each program pair and
// the pipeline made from it. A run that draws one program on many sets of constants (the
// differential run of `tierlift test`) then compiles, validates and hands lavapipe each
// program once, instead of once per set: on lavapipe, pipeline creation and the shader
// compile at the first draw are most of a small draw's cost.
//
// The programs are compiled for any constants (no ir::prepare_for_device specialisation, no
// CodegenOptions::known_*_constants): the constants reach the shader through the uniform
// block only, so one module serves every set. What the draws read stays the same: the
// specialisation only removes work whose result the rules already fix.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/codegen/codegen.h"
#include "tierlift/pass/pass.h"
#include "vk_internal.h"

namespace tierlift::vulkan {

struct PipelineDesc;

class ProgramReuse {
public:
  // The pair compiled under `key` (programs and every codegen option), nullptr if none.
  const codegen::CompiledPair* find_compiled(const std::string& key) const;
  // Keeps `pair` under `key`, with the programs it was compiled from (their addresses are in
  // the key, so they must not be freed and reused while the entry exists).
  void keep_compiled(const std::string& key, std::shared_ptr<const ir::Program> vs,
                     std::shared_ptr<const ir::Program> ps, const codegen::CompiledPair& pair);

  // A pipeline for `desc` (whose render pass and layout only say which formats and bindings
  // the draw has): the one made for the same modules, state, attachments and descriptor
  // bindings before, else one made now with a render pass and layout of the cache's own, which
  // are compatible with the draw's (Vulkan's render pass and pipeline layout compatibility).
  ir::Status pipeline(Device::Impl& d, const PipelineDesc& desc,
                      const std::vector<VkFormat>& color_formats, VkFormat stencil_format,
                      const std::vector<VkDescriptorSetLayoutBinding>& bindings, VkPipeline& out);

  size_t compiled_count() const { return compiled_.size(); }
  size_t pipeline_count() const { return pipelines_.size(); }

private:
  struct Compiled {
    std::shared_ptr<const ir::Program> vs, ps;
    codegen::CompiledPair pair;
  };
  struct Pipeline {
    Cleanup objects; // render pass, set and pipeline layouts, shader modules, the pipeline
    VkPipeline pipeline = VK_NULL_HANDLE;
  };
  std::map<std::string, Compiled, std::less<>> compiled_;
  std::map<std::string, std::unique_ptr<Pipeline>, std::less<>> pipelines_;
};

// The key of compiling `vs` and `ps` with `options` for reuse: the programs by address (a
// null vs: the device's pass-through program), every option that changes the modules.
// nullopt: not reused (a traced draw).
std::optional<std::string> compile_key(const ir::Program* vs, const ir::Program* ps,
                                       const codegen::CodegenOptions& options);

} // namespace tierlift::vulkan
