#include "temp_registry.h"

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>

namespace tierlift::io::detail {
namespace {

constexpr int kSlots = 16;
constexpr size_t kNameBytes = 4096; // PATH_MAX on Linux
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

struct Slot {
  volatile sig_atomic_t active = 0;
  volatile sig_atomic_t folder = 0; // a folder (OutputFolder) rather than a file
  char name[kNameBytes] = {};
};
Slot g_slots[kSlots];
std::mutex g_mutex; // slot allocation between threads; the handler only reads

// Unlinks the entries of a folder using only async-signal-safe calls (open, the raw
// getdents64 system call, unlinkat, close): opendir and std::filesystem allocate. Entries
// are read again after each batch, since unlinking while reading may skip some.
void empty_folder_in_handler(const char* path) {
  for (int pass = 0; pass < 64; ++pass) {
    int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    alignas(8) char buf[4096];
    bool removed = false;
    for (;;) {
      long n = ::syscall(SYS_getdents64, fd, buf, sizeof buf);
      if (n <= 0) break;
      for (long off = 0; off < n;) {
        // struct linux_dirent64: d_ino (8), d_off (8), d_reclen (2), d_type (1), d_name.
        unsigned short reclen = 0;
        std::memcpy(&reclen, buf + off + 16, sizeof reclen);
        const char* name = buf + off + 19;
        const bool dot = name[0] == '.' && (name[1] == 0 || (name[1] == '.' && name[2] == 0));
        if (!dot && ::unlinkat(fd, name, 0) == 0) removed = true;
        off += reclen;
      }
    }
    ::close(fd);
    if (!removed) return;
  }
}

extern "C" void remove_temps_and_die(int sig) {
  // Files first: an AtomicFile's temporary may lie inside an OutputFolder's folder.
  for (Slot& s : g_slots)
    if (s.active && !s.folder) ::unlink(s.name); // async-signal-safe
  for (Slot& s : g_slots)
    if (s.active && s.folder) {
      empty_folder_in_handler(s.name);
      ::rmdir(s.name);
    }
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

// A free slot holding a copy of `pattern`, or -1 (*err set). Called with g_mutex held.
int free_slot(const std::string& pattern, int* err) {
  if (pattern.size() >= kNameBytes) {
    *err = ENAMETOOLONG;
    return -1;
  }
  for (int i = 0; i < kSlots; ++i)
    if (!g_slots[i].active) {
      std::memcpy(g_slots[i].name, pattern.c_str(), pattern.size() + 1);
      return i;
    }
  *err = EMFILE;
  return -1;
}

} // namespace

SignalsBlocked::SignalsBlocked() {
  sigset_t set;
  sigemptyset(&set);
  for (int sig : kSignals) sigaddset(&set, sig);
  ::pthread_sigmask(SIG_BLOCK, &set, &old_);
}

SignalsBlocked::~SignalsBlocked() {
  ::pthread_sigmask(SIG_SETMASK, &old_, nullptr);
}

namespace {

// A free slot named from `pattern`, made into a file or folder by `make` (which fills in the
// X's) and registered with the handlers, all with signals held: a handler never sees a slot
// half made. -1 with *err set when there is no slot or `make` fails.
template <class Make>
int create_registered(const std::string& pattern, int folder, int* err, Make make) {
  install_handlers_once();
  std::lock_guard lock(g_mutex);
  SignalsBlocked blocked;
  int i = free_slot(pattern, err);
  if (i < 0) return -1;
  Slot& s = g_slots[i];
  if (!make(s.name)) {
    *err = errno;
    return -1;
  }
  s.folder = folder;
  s.active = 1;
  return i;
}

} // namespace

int create_registered_temp(const std::string& pattern, int* fd, int* err) {
  return create_registered(pattern, 0, err, [fd](char* name) {
    *fd = ::mkostemp(name, O_CLOEXEC);
    return *fd >= 0;
  });
}

int create_registered_temp_dir(const std::string& pattern, int* err) {
  return create_registered(pattern, 1, err, [](char* name) { return ::mkdtemp(name) != nullptr; });
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

void remove_registered_temp(int slot, bool remove) {
  std::lock_guard lock(g_mutex);
  SignalsBlocked blocked;
  Slot& s = g_slots[slot];
  if (s.active && remove) {
    if (s.folder) {
      std::error_code ec;
      std::filesystem::remove_all(s.name, ec);
    } else {
      ::unlink(s.name);
    }
  }
  s.active = 0;
}

} // namespace tierlift::io::detail
