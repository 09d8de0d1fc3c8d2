// When a test may skip. A plain clone on a machine without Vulkan (or without the shared
// corpus next to the repository) skips the tests that need them; CI sets
//   TIERLIFT_REQUIRE_VULKAN=1   a test that needs a Vulkan device fails instead of skipping
//   TIERLIFT_REQUIRE_CORPUS=1   a test that needs the shared corpus fails instead of skipping
// so a driver that stopped loading, or a corpus that went missing, cannot turn a run green
// by skipping what it could not run.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>

namespace tierlift::test {

inline constexpr const char* kRequireVulkan = "TIERLIFT_REQUIRE_VULKAN";
inline constexpr const char* kRequireCorpus = "TIERLIFT_REQUIRE_CORPUS";

// Set and neither empty nor "0".
inline bool required(const char* env_var) {
  const char* v = std::getenv(env_var);
  return v && *v && std::strcmp(v, "0") != 0;
}

} // namespace tierlift::test

// Skips the current test with `why`, or fails it when `env_var` requires what is missing.
// Like GTEST_SKIP and FAIL it returns from the (void) function it is used in.
#define TIERLIFT_SKIP_UNLESS_REQUIRED(env_var, why)                                                \
  do {                                                                                             \
    const std::string tl_why_ = (why);                                                             \
    if (::tierlift::test::required(env_var))                                                       \
      FAIL() << tl_why_ << " [" << (env_var) << " is set: this test must run, not skip]";          \
    GTEST_SKIP() << tl_why_;                                                                       \
  } while (0)
