// The cases of a corpus run (`tierlift test`): every shader found under the paths given —
// files, folders (recursively) and list files — each with an id that stays the same on every
// machine: its path relative to the root it was found under (the root's own name first), an
// '@', and a hash of its bytes. A changed file is a new case; a moved root is not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/ir/result.h"

namespace tierlift::corpus {

struct Case {
  std::string id;   // "listings/glow/downsample4.psh@3f09a1c2b7d4e865"
  std::string path; // the file to read; empty for a generated case
  std::string text; // a generated case's listing (the file's bytes are read by the worker)
  // A generated case: the generator's inputs, so that one command reproduces it alone.
  bool generated = false;
  std::string gen_profile;
  uint64_t gen_seed = 0;
  size_t gen_index = 0;
};

// FNV-1a, 64 bits: the content hash of an id and the shard key (the same on every machine).
uint64_t fnv1a64(std::string_view bytes);
std::string hex64(uint64_t v);

// The id of `bytes` found at `relative` (forward slashes).
std::string case_id(std::string_view relative, std::string_view bytes);

// The cases under `roots`, sorted by id, duplicates (same id) once:
//   * a folder: every regular file below it (hidden entries skipped) that holds a listing:
//     a token stream, a C array of one, or text with a version line (vs_/ps_ x_y) — so READMEs,
//     images, scene files and #include fragments are left out;
//   * a file: a list file when it is text whose every non-blank line not starting with '#'
//     names an existing file or folder (relative to the list file); else one case, whatever
//     it holds (a broken file given by name is a failing case, not something to skip).
// A root that does not exist, or cannot be read, is an error (rule "io").
ir::Result<std::vector<Case>> discover(const std::vector<std::string>& roots);

// Whether `bytes` (a file found in a folder) holds a listing (see discover).
bool looks_like_listing(std::string_view bytes);

// `count` generated programs of `profile` (gen::generate_listing, seeded by `seed` and each
// index, with the options the differential run binds: 2D samplers, one colour output), ids
// "generated/<profile>/seed<seed>/<index, 5 digits>@<hash>", in index order; made on
// `threads` threads (0: one a core), the same cases on any number. A profile the generator
// does not write fails as generate_listing does.
ir::Result<std::vector<Case>> generated_cases(const std::string& profile, uint64_t seed,
                                              size_t count, unsigned threads = 0);

// --shard I/N: the case belongs to shard `index` of `count` (by fnv1a64 of the id).
bool in_shard(const Case& c, size_t index, size_t count);

} // namespace tierlift::corpus
