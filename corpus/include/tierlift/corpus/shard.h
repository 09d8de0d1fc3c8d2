// --shard I/N balanced by cost (`--shard-costs FILE`): where an earlier run's results.jsonl
// says how long each case took, the shards get about the same total time instead of about
// the same number of cases. The partition depends only on the case ids and the cost file, so
// every machine given the same file computes the same shards, and each case is in exactly
// one of them (`tierlift test merge` of the shards is the single run).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "tierlift/corpus/cases.h"
#include "tierlift/ir/result.h"

namespace tierlift::corpus {

// Microseconds per id from a results.jsonl (its "ms", the first attempt's). A missing or
// unreadable file is an error (rule "io"); lines that are not results are left out.
ir::Result<std::map<std::string, uint64_t>> read_costs(const std::string& results_jsonl);

// Shard `index` of `count` by longest processing time first: the cases sorted by cost
// (largest first, ties by id), each given to the shard whose total is smallest so far (ties:
// the lowest shard). A case the costs do not name (a new or edited file) costs the median of
// the known costs (1 when none is known). Returns the shard's cases in their input order.
std::vector<Case> balanced_shard(const std::vector<Case>& cases,
                                 const std::map<std::string, uint64_t>& costs, size_t index,
                                 size_t count);

// The order a run hands its cases out in: costliest first (longest processing time first),
// so that a long case does not start last while the other workers run out of work and wait
// for it. `which` are positions in `cases`; the result is the same positions reordered. With
// costs (an earlier run's, read_costs), a case they do not name costs their median, as in
// balanced_shard; with none (or none that names one of these cases), a case costs its size
// in bytes (its file's, or a generated
// case's text), which on the bytecode corpora follows the time closely enough to put the few
// long cases first. Equal costs keep the order of `which`.
std::vector<size_t> costliest_first(const std::vector<Case>& cases, std::vector<size_t> which,
                                    const std::map<std::string, uint64_t>& costs);

} // namespace tierlift::corpus
