// A corpus run replaces the files in its output folder. When one of them is also a file the
// run reads (a --baseline kept as DIR/failures.csv, a --shard-costs that is DIR/results.jsonl,
// a listing), the run would overwrite its own input: a baseline so replaced holds this run's
// failures, and the next run would accept them as expected. Such a run is refused before
// anything is written.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "tierlift/ir/result.h"

namespace tierlift::corpus {

// The files a run or a merge writes in `dir`: results.jsonl, results.csv, failures.csv,
// junit.xml, summary.md, and a run's workers.log.
std::vector<std::string> output_files(const std::string& dir);

// Success when none of `inputs` is one of output_files(dir) (the same file: device and
// inode, whatever the names or links); otherwise a failure (rule "write") naming both. Each
// output that exists is looked up once and each input once, so a corpus of many listings
// costs one stat a listing.
ir::Status refuse_outputs_among_inputs(const std::string& dir, std::span<const std::string> inputs);

// Success when `dir` does not exist, is empty, or holds a run's results (a results.jsonl):
// a run replaces its report files there, and in a folder of other files (`-o .` in a project)
// one of them could be the user's own summary.md or results.csv. Otherwise a failure (rule
// "write") that says so.
ir::Status refuse_foreign_folder(const std::string& dir);

} // namespace tierlift::corpus
