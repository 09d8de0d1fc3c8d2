// The peer both front-end and translation benchmarks measure against: glslang compiling
// GLSL that does the work of the article's Listings 1 and 2.
#pragma once

#include <cstdint>
#include <vector>

#include <glslang/Public/ShaderLang.h>

namespace tierlift::bench {

// GLSL doing the work of Listing 1 (8 offset texcoords) and Listing 2 (8 weighted taps).
extern const char* const kGlslVertex8;
extern const char* const kGlslFragment8;

// One glslang compile (parse, link, SPIR-V generation) for Vulkan 1.1 / SPIR-V 1.3; empty on
// failure. glslang::InitializeProcess() must have been called.
std::vector<uint32_t> glslang_to_spirv(EShLanguage stage, const char* source);

} // namespace tierlift::bench
