// cpu_features.h: asked once per process.
#include "tierlift/cpu/cpu_features.h"

#include <cstdlib>
#include <cstring>

namespace tierlift::cpu {
namespace {

bool baseline_asked() {
  const char* v = std::getenv("TIERLIFT_CPU_BASELINE");
  return v && *v && std::strcmp(v, "0") != 0;
}

} // namespace

bool cpu_runs_avx2() {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool yes = !baseline_asked() && __builtin_cpu_supports("avx2");
  return yes;
#else
  return false;
#endif
}

bool cpu_runs_avx2_fma() {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool yes = cpu_runs_avx2() && __builtin_cpu_supports("fma");
  return yes;
#else
  return false;
#endif
}

} // namespace tierlift::cpu
