// A folder of outputs written as one (glow -o DIR, report -o DIR, report --stress -o DIR):
// after a run DIR holds all of that run's files or is as it was, never a mix.
//  - The files are written into a hidden temporary folder: inside DIR when DIR exists
//    (".tierlift-tmpXXXXXX", the same file system as its files), else beside where DIR
//    will be (".DIR.tmpXXXXXX" in the nearest folder that exists). It is removed when the
//    folder is destroyed uncommitted and when SIGINT, SIGTERM or SIGHUP ends the process,
//    so an interrupted run leaves neither it nor an empty DIR behind.
//  - commit(): a DIR that did not exist is the temporary folder renamed (one step; missing
//    parent folders are made first). Into a DIR that exists each file is renamed in with
//    those signals held back until the last one is in place.
//  - A manifest, DIR/.tierlift-written-TAG, names the files the last run of that kind
//    (TAG: "glow", "report", …) wrote. The next run removes those it does not write again,
//    so new and stale outputs never mix; every other file in DIR is the user's and is never
//    touched (a user's file with the name of an output is replaced, as -o replaces a file).
//  - A name whose DIR/name is one of the run's inputs (same device and inode) is refused
//    before anything is written, and an input is never removed as stale.
#pragma once

#include <string>
#include <vector>

#include "tierlift/ir/result.h"

namespace tierlift::io {

class OutputFolder {
public:
  // Makes the temporary folder. A failure (DIR is a file, no folder on the way to it can be
  // written) is kept: status() says it, and path() and commit() return it.
  OutputFolder(std::string dir, std::vector<std::string> inputs, std::string tag);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  // The first failure so far (rule "write", "DIR: what failed: why"), or success.
  ir::Status status() const;
  const std::string& dir() const { return dir_; }
  // The temporary folder, for scratch files that are not outputs (removed with it).
  const std::string& temp_dir() const { return temp_; }

  // Where to write the output `name` (a file name, no '/'): its place in the temporary
  // folder. Fails when DIR/name is one of the inputs or a folder; the name is recorded.
  ir::Result<std::string> path(const std::string& name);
  // DIR/name, the path an output will have once committed.
  std::string final_path(const std::string& name) const;

  // Moves every recorded output into DIR (see above); their final paths, in the order
  // they were named. On failure before the first rename DIR is untouched.
  ir::Result<std::vector<std::string>> commit();

private:
  ir::Failure fail(std::string message); // keeps the first failure; returns it
  std::string dir_, tag_, temp_, error_;
  std::vector<std::string> inputs_, names_;
  bool dir_existed_ = false;
  int slot_ = -1;
};

// The manifest's name for `tag`: ".tierlift-written-" + tag.
std::string output_manifest_name(const std::string& tag);

} // namespace tierlift::io
