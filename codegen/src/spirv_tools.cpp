// SPIRV-Tools in-process: validation (Vulkan 1.1 rules), disassembly and optimisation.
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include "tierlift/codegen/codegen.h"

namespace tierlift::codegen {
namespace {

constexpr spv_target_env kEnv = SPV_ENV_VULKAN_1_1;

// Collects every message the tools print, so a failure carries the validator's own words.
struct MessageCollector {
  std::string text;
  spvtools::MessageConsumer consumer() {
    return [this](spv_message_level_t, const char*, const spv_position_t& pos, const char* msg) {
      if (!text.empty()) text += '\n';
      text += "word " + std::to_string(pos.index) + ": " + msg;
    };
  }
};

} // namespace

ir::Status validate(const std::vector<uint32_t>& words) {
  spvtools::SpirvTools tools(kEnv);
  MessageCollector messages;
  tools.SetMessageConsumer(messages.consumer());
  spvtools::ValidatorOptions options;
  if (tools.Validate(words.data(), words.size(), options)) return ir::ok_status();
  return ir::fail("spirv-val", "spirv", messages.text.empty() ? "spirv-val failed" : messages.text);
}

ir::Result<std::string> disassemble(const std::vector<uint32_t>& words) {
  spvtools::SpirvTools tools(kEnv);
  MessageCollector messages;
  tools.SetMessageConsumer(messages.consumer());
  std::string text;
  if (!tools.Disassemble(words, &text,
                         SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES |
                             SPV_BINARY_TO_TEXT_OPTION_INDENT))
    return ir::fail("spirv-dis", "spirv",
                    messages.text.empty() ? "spirv-dis failed" : messages.text);
  return text;
}

ir::Status optimize(std::vector<uint32_t>& words) {
  spvtools::Optimizer opt(kEnv);
  MessageCollector messages;
  opt.SetMessageConsumer(messages.consumer());
  opt.RegisterPerformancePasses();
  std::vector<uint32_t> out;
  if (!opt.Run(words.data(), words.size(), &out))
    return ir::fail("spirv-opt", "spirv",
                    messages.text.empty() ? "spirv-opt failed" : messages.text);
  words = std::move(out);
  return ir::ok_status();
}

} // namespace tierlift::codegen
