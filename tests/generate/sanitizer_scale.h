// How many generated listings a test walks: the full count in a plain build, a smaller one
// under a sanitizer (ASan and TSan run the parser and validator 10–20× slower, and the
// thousands-of-seeds tests then took most of the sanitized ctest run). The smaller counts
// still cover every profile; the plain build keeps the thousands.
#pragma once

#include <cstddef>

namespace tierlift::gen::test {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) ||                         \
    __has_feature(memory_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

// `full` in a plain build, `sanitized` under a sanitizer.
constexpr std::size_t scaled_count(std::size_t full, std::size_t sanitized) {
  return kSanitized ? sanitized : full;
}

} // namespace tierlift::gen::test
