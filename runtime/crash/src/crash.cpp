// The crash handler (crash.h). Everything after a signal arrives is async-signal-safe:
// plain loops over fixed buffers, write(2), sigaction(2), signal(2) and raise(3). The text it needs
// is composed earlier, in normal context, when install_handler runs and when a Stage begins.
#include "tierlift/crash/crash.h"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace tierlift::crash {
namespace {

constexpr size_t kCommandBytes = 64;
constexpr size_t kStageBytes = 512;

// The command, as printed and as a JSON string body.
char g_command[kCommandBytes] = "tierlift";
char g_command_json[2 * kCommandBytes] = "tierlift";
// Two copies of the stage (text and JSON string body); a new stage is written into the one
// the handler is not reading, then made active, so the handler never sees half a stage.
char g_stage[2][kStageBytes];
char g_stage_json[2][2 * kStageBytes];
std::atomic<int> g_active{0};
std::atomic<bool> g_json{false};
std::atomic<bool> g_document_written{false};

constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL};
constexpr size_t kSignalCount = sizeof kSignals / sizeof kSignals[0];
struct sigaction g_previous[kSignalCount]; // what each signal did before install_handler

// Bounded copy that always terminates `dst`.
void copy(char* dst, size_t size, std::string_view src) {
  const size_t n = src.size() < size - 1 ? src.size() : size - 1;
  std::memcpy(dst, src.data(), n);
  dst[n] = '\0';
}

// `src` as the body of a JSON string (quotes, backslashes and control characters escaped),
// cut at a character boundary of the escaped form.
void copy_json(char* dst, size_t size, std::string_view src) {
  static constexpr char kHex[] = "0123456789abcdef";
  size_t n = 0;
  for (const char ch : src) {
    const auto c = static_cast<unsigned char>(ch);
    char piece[7];
    size_t len = 0;
    if (c == '"' || c == '\\') {
      piece[len++] = '\\';
      piece[len++] = static_cast<char>(c);
    } else if (c < 0x20) {
      for (const char p : {'\\', 'u', '0', '0', kHex[c >> 4], kHex[c & 15]}) piece[len++] = p;
    } else {
      piece[len++] = static_cast<char>(c);
    }
    if (n + len >= size) break;
    std::memcpy(dst + n, piece, len);
    n += len;
  }
  dst[n] = '\0';
}

void set_stage(std::string_view what) {
  const int next = 1 - g_active.load();
  copy(g_stage[next], kStageBytes, what);
  copy_json(g_stage_json[next], sizeof g_stage_json[next], what);
  g_active.store(next);
}

const char* signal_words(int sig) {
  switch (sig) {
  case SIGSEGV: return "SIGSEGV, segmentation fault";
  case SIGBUS: return "SIGBUS, bus error";
  case SIGABRT: return "SIGABRT, abort";
  case SIGFPE: return "SIGFPE, arithmetic exception";
  case SIGILL: return "SIGILL, illegal instruction";
  default: return "a fatal signal";
  }
}

// Appends to a fixed buffer without a library call that might allocate or lock.
struct Writer {
  char* buf;
  size_t size;
  size_t n = 0;
  void add(const char* s) {
    for (; *s && n + 1 < size; ++s) buf[n++] = *s;
    buf[n] = '\0';
  }
  void add_number(int v) {
    char digits[12];
    int k = 0;
    unsigned u = v < 0 ? 0u : static_cast<unsigned>(v);
    do {
      digits[k++] = static_cast<char>('0' + u % 10);
      u /= 10;
    } while (u && k < 11);
    while (k > 0 && n + 1 < size) buf[n++] = digits[--k];
    buf[n] = '\0';
  }
};

// "crashed (SIGSEGV, segmentation fault) in the Vulkan driver while creating the device"
void add_message(Writer& w, int sig, const char* stage) {
  w.add("crashed (");
  w.add(signal_words(sig));
  w.add(")");
  w.add(stage[0] ? " " : " outside any recorded stage");
  w.add(stage);
}

size_t compose_line(char* buf, size_t size, int sig) {
  Writer w{buf, size};
  w.add("tierlift ");
  w.add(g_command);
  w.add(": error: ");
  add_message(w, sig, g_stage[g_active.load()]);
  return w.n;
}

void write_all(int fd, const char* p, size_t n) {
  while (n > 0) {
    const ssize_t k = write(fd, p, n);
    if (k <= 0) return;
    p += k;
    n -= static_cast<size_t>(k);
  }
}

// The document every command prints under --json (cli/report.h), with one "crash" error.
void write_json(int sig) {
  static char doc[4 * kStageBytes];
  Writer w{doc, sizeof doc};
  w.add("{\n  \"command\": \"");
  w.add(g_command_json);
  w.add("\",\n  \"exit_code\": ");
  w.add_number(128 + sig);
  w.add(",\n  \"ok\": false,\n  \"diagnostics\": [\n    {\n      \"file\": \"\",\n      "
        "\"line\": 0,\n      \"column\": 0,\n      \"length\": 0,\n      \"severity\": "
        "\"error\",\n      \"rule\": \"crash\",\n      \"message\": \"");
  add_message(w, sig, g_stage_json[g_active.load()]);
  w.add("\"\n    }\n  ],\n  \"result\": {}\n}\n");
  write_all(STDOUT_FILENO, doc, w.n);
}

void on_crash(int sig) {
  // Under --json the document is the whole output (standard error stays empty); once the
  // command printed its own, a crash after it (a driver's exit code) gets the line instead.
  if (g_json.load() && !g_document_written.exchange(true)) {
    write_json(sig);
  } else {
    static char line[2 * kStageBytes];
    const size_t n = compose_line(line, sizeof line - 1, sig);
    line[n] = '\n';
    write_all(STDERR_FILENO, line, n + 1);
  }
  // The action from before install_handler (the default, so the exit status stays
  // 128 + signal and a core can be dumped; under AddressSanitizer its own report).
  bool restored = false;
  for (size_t i = 0; i < kSignalCount; ++i)
    if (kSignals[i] == sig) restored = sigaction(sig, &g_previous[i], nullptr) == 0;
  if (!restored) signal(sig, SIG_DFL);
  raise(sig);
}

} // namespace

void install_handler(std::string_view command, bool json) {
  copy(g_command, kCommandBytes, command);
  copy_json(g_command_json, sizeof g_command_json, command);
  g_json.store(json);
  // An alternate stack, so a stack overflow still gets its line.
  static char alt_stack[1 << 16];
  stack_t ss{};
  ss.ss_sp = alt_stack;
  ss.ss_size = sizeof alt_stack;
  sigaltstack(&ss, nullptr);
  struct sigaction sa {};
  sa.sa_handler = on_crash;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_ONSTACK | SA_RESETHAND;
  for (size_t i = 0; i < kSignalCount; ++i) sigaction(kSignals[i], &sa, &g_previous[i]);
}

void document_written() {
  g_document_written.store(true);
}

Stage::Stage(std::string_view id, std::string_view what) : previous_(current_stage()) {
  set_stage(what);
  if (const char* test = std::getenv("TIERLIFT_TEST_CRASH"); test && id == test) raise(SIGSEGV);
}

Stage::~Stage() {
  set_stage(previous_);
}

std::string current_stage() {
  return g_stage[g_active.load()];
}

std::string crash_line(int signal) {
  char line[2 * kStageBytes];
  const size_t n = compose_line(line, sizeof line, signal);
  return std::string(line, n);
}

} // namespace tierlift::crash
