// Which build of the block loops runs (tierlift/cpu/cpu_features.h). The ctest entries
// cpu_baseline_draw and cpu_baseline_vm (tests/CMakeLists.txt) run the identity tests with
// TIERLIFT_CPU_BASELINE=1, and this test with them, so that a setting that did not take
// fails instead of checking the AVX2 builds a second time.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "tierlift/cpu/cpu_features.h"

namespace tierlift::cpu {
namespace {

TEST(CpuFeatures, BaselineWhenAskedElseWhatTheCpuHas) {
  const char* v = std::getenv("TIERLIFT_CPU_BASELINE");
  if (v && *v && std::strcmp(v, "0") != 0) {
    EXPECT_FALSE(cpu_runs_avx2());
    EXPECT_FALSE(cpu_runs_avx2_fma());
    return;
  }
#if defined(__x86_64__) && defined(__GNUC__)
  const bool avx2 = __builtin_cpu_supports("avx2") != 0;
  EXPECT_EQ(cpu_runs_avx2(), avx2);
  EXPECT_EQ(cpu_runs_avx2_fma(), avx2 && __builtin_cpu_supports("fma") != 0);
#else
  EXPECT_FALSE(cpu_runs_avx2());
  EXPECT_FALSE(cpu_runs_avx2_fma());
#endif
}

} // namespace
} // namespace tierlift::cpu
