#include "temp_registry.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <mutex>

namespace tierlift::io::detail {
namespace {

constexpr int kSlots = 16;
constexpr size_t kNameBytes = 4096; // PATH_MAX on Linux
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

struct Slot {
  volatile sig_atomic_t active = 0;
  char name[kNameBytes] = {};
};
Slot g_slots[kSlots];
std::mutex g_mutex; // slot allocation between threads; the handler only reads

extern "C" void remove_temps_and_die(int sig) {
  for (Slot& s : g_slots)
    if (s.active) ::unlink(s.name); // async-signal-safe
  // Back to the default action; the signal is blocked while we run, so it is delivered
  // (and ends the process as it would have) as soon as the handler returns.
  std::signal(sig, SIG_DFL);
  ::raise(sig);
}

void install_handlers_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : kSignals) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0) continue;
      // Someone else's handler, or an ignored signal (nohup): leave it alone.
      if (old.sa_handler != SIG_DFL || (old.sa_flags & SA_SIGINFO)) continue;
      struct sigaction sa {};
      sa.sa_handler = remove_temps_and_die;
      sigemptyset(&sa.sa_mask);
      for (int other : kSignals) sigaddset(&sa.sa_mask, other);
      ::sigaction(sig, &sa, nullptr);
    }
  });
}

// Blocks the three signals for its lifetime.
struct SignalsBlocked {
  sigset_t old;
  SignalsBlocked() {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : kSignals) sigaddset(&set, sig);
    ::pthread_sigmask(SIG_BLOCK, &set, &old);
  }
  ~SignalsBlocked() { ::pthread_sigmask(SIG_SETMASK, &old, nullptr); }
};

} // namespace

int create_registered_temp(const std::string& pattern, int* fd, int* err) {
  install_handlers_once();
  if (pattern.size() >= kNameBytes) {
    *err = ENAMETOOLONG;
    return -1;
  }
  std::lock_guard lock(g_mutex);
  for (int i = 0; i < kSlots; ++i) {
    Slot& s = g_slots[i];
    if (s.active) continue;
    SignalsBlocked blocked;
    std::memcpy(s.name, pattern.c_str(), pattern.size() + 1);
    *fd = ::mkostemp(s.name, O_CLOEXEC);
    if (*fd < 0) {
      *err = errno;
      return -1;
    }
    s.active = 1;
    return i;
  }
  *err = EMFILE;
  return -1;
}

std::string registered_temp_name(int slot) {
  return g_slots[slot].name;
}

bool rename_registered_temp(int slot, const std::string& target, int* err) {
  std::lock_guard lock(g_mutex);
  SignalsBlocked blocked;
  Slot& s = g_slots[slot];
  if (std::rename(s.name, target.c_str()) != 0) {
    *err = errno;
    return false;
  }
  s.active = 0;
  return true;
}

void remove_registered_temp(int slot, bool unlink_file) {
  std::lock_guard lock(g_mutex);
  SignalsBlocked blocked;
  Slot& s = g_slots[slot];
  if (s.active && unlink_file) ::unlink(s.name);
  s.active = 0;
}

} // namespace tierlift::io::detail
