// What a crash says. A fault that the code cannot foresee (a driver that segfaults inside
// vkCreateDevice, an abort in a library) would otherwise end the process with a bare exit
// status 128 + signal and no word. install_handler catches SIGSEGV, SIGBUS, SIGABRT, SIGFPE
// and SIGILL, writes one line naming the stage that was running on standard error (under
// --json instead the JSON document every command prints, with that line as its error), then
// restores the action it replaced (the default one, or a sanitizer's) and raises the signal
// again, so the exit status stays 128 + signal and a core dump is still possible.
//
// The handler uses only async-signal-safe calls (write, sigaction, signal, raise): everything it
// prints is composed before the crash, when a Stage begins, into fixed buffers.
#pragma once

#include <string>
#include <string_view>

namespace tierlift::crash {

// Installs the handler for the process. `command` names the subcommand ("run", "glow") in
// the line and the JSON document; `json`: the command prints one JSON document on standard
// output, so the crash prints one too.
void install_handler(std::string_view command, bool json);

// The command printed its own JSON document: a crash from here on (e.g. in a driver's exit
// code) writes the line only, so standard output keeps exactly one document.
void document_written();

// The stage running now, for the handler's line, from construction to destruction (scopes
// nest; the outer stage is back when the inner one ends). `id` is a short name, `what` the
// words after "crashed": "in the Vulkan driver while creating the device".
//
// Test hook: when the environment variable TIERLIFT_TEST_CRASH equals `id`, the constructor
// raises SIGSEGV once the stage is recorded, so tests can check the handler's output without
// a real fault.
class Stage {
public:
  Stage(std::string_view id, std::string_view what);
  ~Stage();
  Stage(const Stage&) = delete;
  Stage& operator=(const Stage&) = delete;

private:
  std::string previous_;
};

// The words of the stage running now ("" when none); for tests.
std::string current_stage();

// The line the handler writes for `signal` in the stage running now, without the newline:
// "tierlift run: error: crashed (SIGSEGV, segmentation fault) in the Vulkan driver while
// creating the device". For tests; the handler writes the same bytes.
std::string crash_line(int signal);

} // namespace tierlift::crash
