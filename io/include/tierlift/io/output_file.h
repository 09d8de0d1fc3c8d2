// Writing an output file without ever losing a user's file:
//  - "-" is standard output;
//  - a FIFO or a character device (a terminal, /dev/null, /dev/stdout) is written straight
//    through, never replaced by a regular file;
//  - a symbolic link is followed: the file it points to is replaced, the link stays;
//  - anything else is written to a hidden temporary file beside the target and renamed over
//    it, so a failed or interrupted write leaves the old file (or none) and no half-written
//    one; the temporary file is removed when SIGINT, SIGTERM or SIGHUP ends the process;
//  - an output that is one of the command's inputs (the same device and inode, whatever
//    the names) is refused before anything is written (refuse_if_input).
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "tierlift/ir/result.h"

namespace tierlift::io {

// Writes `bytes` to `path` as above. A failure (rule "write") says "PATH: what failed: why".
ir::Status write_output(const std::string& path, std::string_view bytes);

// True when `a` and `b` both exist and are the same file (device and inode, symbolic links
// followed). "-" is never the same as a file.
bool same_file(const std::string& a, const std::string& b);

// Success when `output` is none of `inputs`; otherwise a failure (rule "write") naming both.
ir::Status refuse_if_input(const std::string& output, std::span<const std::string> inputs);

// A temporary file beside a target, renamed over the target by commit(); removed by the
// destructor when not committed, and by SIGINT/SIGTERM/SIGHUP while it exists. Exposed for
// writers that produce their bytes in pieces, and for the test of the signal clean-up.
class AtomicFile {
public:
  // Creates the temporary file beside `target` (after following symbolic links). A failure
  // to do so is kept: status() says it, and write and commit return it.
  explicit AtomicFile(const std::string& target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // The first failure so far (rule "write", "PATH: what failed: why"), or success.
  ir::Status status() const;
  const std::string& temp_path() const { return temp_; }
  ir::Status write(std::string_view bytes);
  // fsync, close and rename over the target. On failure the temporary is removed (by the
  // destructor) and the target is untouched.
  ir::Status commit();

private:
  void fail(const std::string& what, int err);
  std::string target_, shown_, temp_, error_;
  int fd_ = -1;
  int slot_ = -1;
  bool committed_ = false;
};

} // namespace tierlift::io
