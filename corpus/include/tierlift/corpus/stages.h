// One case through the whole lift, stage by stage: parse, validate, token round trip,
// SPIR-V (spirv-val), and the differential run (the interpreter against Vulkan on K
// generated input sets). Runs in the calling process: the coordinator puts each call in a
// worker process (runner.h), so that a crash or a hang here costs one case.
#pragma once

#include <cstdint>
#include <string>

#include "tierlift/corpus/cases.h"
#include "tierlift/corpus/result.h"

namespace tierlift::vulkan {
class Device;
}

namespace tierlift::corpus {

struct StageOptions {
  unsigned input_sets = 3; // K: the differential run draws the case K times
  uint64_t seed = 1;       // of the generated inputs (with the case id: per case)
  uint32_t size = 8;       // the target is size × size pixels, RGBA32F
  bool check_only = false; // parse and validate only (no round trip, SPIR-V or draw)
  // The Vulkan side compiles the case once for all K sets, its constants in the uniform block
  // (effects::VulkanPassOptions::reuse_programs). false: a module and pipeline per set,
  // specialised for its constants, as before (bench/corpus_bench.cpp measures both).
  bool one_pipeline_per_case = true;
  // The Vulkan device of the differential run; null: the stage is skipped ("no device").
  vulkan::Device* device = nullptr;
};

// The case's bytes: its file (read within the listing cap) or its generated text.
CaseResult run_case(const Case& c, const StageOptions& options);

// The same on bytes already in hand (the reducer's predicate runs this on every candidate).
CaseResult run_listing(const std::string& id, const std::string& display_path, std::string bytes,
                       const StageOptions& options);

} // namespace tierlift::corpus
