// LeakSanitizer (CI runs every suite under ASan): Mesa's lavapipe driver, LLVM (its JIT) and
// the Khronos validation layer keep a few allocations for the process's lifetime that they
// never free. They are not ours, so they are suppressed by module (the same list as
// tests/lsan.supp, which says why the Vulkan loader is not on it); any leak in tierlift's own
// code still fails the run, and Vulkan objects it forgets are the validation layer's report. The
// sanitizer runtime calls this weak hook when it is present; in other builds it is an unused
// function.
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libvulkan_lvp.so\n"
         "leak:libLLVM\n"
         "leak:libVkLayer_khronos_validation.so\n";
}
