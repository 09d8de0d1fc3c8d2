// Standard output is an output like any other: a write that fails (a full disk, /dev/full,
// a closed descriptor) is an I/O error (exit 2 in the CLI), never a silent success.
#pragma once

#include <string>

namespace tierlift::io {

// Call first in main(). A standard descriptor that was closed at start (`>&-`) is opened
// on /dev/null the wrong way round (standard output and error read-only, standard input
// write-only), so that every write to it fails as a closed one would, and no file the
// program opens later can take its number (a listing read, or an output's temporary file,
// silently receiving what was meant for standard output).
void guard_standard_streams();

// Flushes standard output and says whether every write to it so far succeeded: "" or
// "<stdout>: write failed: why".
std::string flush_stdout();

// Registers, once, an exit-time check (atexit): when flush_stdout() fails, "PROGRAM:
// error: <stdout>: write failed: why" goes to standard error and the process exits 2 —
// whatever the command returned, since what it printed was lost.
void check_stdout_at_exit(const std::string& program);

} // namespace tierlift::io
