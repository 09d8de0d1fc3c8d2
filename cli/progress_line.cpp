#include "progress_line.h"

#include <chrono>
#include <memory>
#include <unistd.h>

#include <fmt/format.h>

namespace tierlift::cli {
namespace {
bool g_enabled = false;
} // namespace

void set_frame_progress(bool enabled) {
  g_enabled = enabled;
}

effects::FrameProgress frame_progress_line(const std::string& device) {
  if (!g_enabled || isatty(STDERR_FILENO) == 0) return {};
  using Clock = std::chrono::steady_clock;
  // Shared by the copies std::function makes: the time of the last line written.
  auto last = std::make_shared<Clock::time_point>();
  return [device, last](unsigned done, unsigned frames) {
    const Clock::time_point now = Clock::now();
    if (done == frames) { // the run's own summary follows: leave no half line behind
      fmt::print(stderr, "\r\033[K");
      return;
    }
    if (done != 1 && now - *last < std::chrono::milliseconds(100)) return;
    *last = now;
    fmt::print(stderr, "\r\033[K[glow] {}: frame {}/{}", device, done, frames);
  };
}

} // namespace tierlift::cli
