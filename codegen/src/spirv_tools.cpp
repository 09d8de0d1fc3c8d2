// SPIRV-Tools in-process: validation (Vulkan 1.1 rules), disassembly and optimisation.
#include <map>
#include <mutex>

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

// Modules spirv-val passed, by a hash of their words (each compared whole before it counts):
// validation depends on the words alone, and the same module comes back often (the
// pass-through stage of every `tierlift test` case, a reduced program tried again). Bounded:
// emptied when full.
class ValidModules {
public:
  bool contains(const std::vector<uint32_t>& words) {
    std::lock_guard lock(mutex_);
    auto [first, last] = modules_.equal_range(hash(words));
    for (auto it = first; it != last; ++it)
      if (it->second == words) return true;
    return false;
  }
  void add(const std::vector<uint32_t>& words) {
    std::lock_guard lock(mutex_);
    if (modules_.size() >= kMaxModules) modules_.clear();
    modules_.emplace(hash(words), words);
  }

private:
  static constexpr size_t kMaxModules = 64;
  static uint64_t hash(const std::vector<uint32_t>& words) {
    uint64_t h = 0xcbf29ce484222325ull; // FNV-1a over the words
    for (uint32_t w : words) h = (h ^ w) * 0x100000001b3ull;
    return h;
  }
  std::mutex mutex_;
  std::multimap<uint64_t, std::vector<uint32_t>> modules_;
};

ValidModules& valid_modules() {
  static ValidModules modules;
  return modules;
}

} // namespace

ir::Status validate(const std::vector<uint32_t>& words) {
  if (valid_modules().contains(words)) return ir::ok_status();
  spvtools::SpirvTools tools(kEnv);
  MessageCollector messages;
  tools.SetMessageConsumer(messages.consumer());
  spvtools::ValidatorOptions options;
  // The friendly names (%float_1, %_ptr_Input_v4float) serve only the messages of a module
  // that fails, yet spirv-val builds them for every id of every module before it starts: a
  // third of its time on a `tierlift test` case. A module is checked without them, and one
  // that fails is checked again with them, so its messages read as before.
  options.SetFriendlyNames(false);
  if (tools.Validate(words.data(), words.size(), options)) {
    valid_modules().add(words);
    return ir::ok_status();
  }
  messages.text.clear();
  options.SetFriendlyNames(true);
  tools.Validate(words.data(), words.size(), options);
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
