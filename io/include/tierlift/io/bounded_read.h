// Reading a whole input file with a size cap per kind of input. Every reader of the project
// goes through here, so that /dev/zero, /dev/urandom, a pipe or a huge file given where a
// listing, token file, scene or image belongs is refused cheaply: a regular file is measured
// (fstat) before a byte is read, and anything else (pipes, devices, standard input) is read
// for at most cap + 1 bytes.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "tierlift/ir/result.h"

namespace tierlift::io {

// The largest input of one kind that is read, and the kind's name for messages.
struct ReadCap {
  uint64_t bytes;
  std::string_view kind; // "listing", "scene", ...
};

// The caps of the project's inputs (docs/command-line.md lists them). Each is far above
// what a legal input of that kind needs: a D3D9 shader is at most a few thousand
// instructions, a scene is a page of JSON, an image is bounded by the decode budget.
inline constexpr ReadCap kListingCap{uint64_t{4} << 20, "listing"};      // 4 MiB of text
inline constexpr ReadCap kTokenFileCap{uint64_t{4} << 20, "token file"}; // raw or C array
inline constexpr ReadCap kSceneCap{uint64_t{1} << 20, "scene"};          // 1 MiB of JSON
inline constexpr ReadCap kImageFileCap{uint64_t{1} << 30, "image file"}; // 1 GiB PNG/PFM

// Looks at the first bytes read (at most 64 KiB, fewer for a shorter input); a failure stops
// reading at once. An image reader uses it to refuse a file with no image signature before
// reading more of it.
using PrefixCheck = std::function<ir::Status(std::string_view first_bytes)>;

// Reads `path` ("-" = standard input) whole. A failure (rule "io", message "PATH: ...") when
// it cannot be opened, is a directory, is larger than `cap` (the message names the cap) or a
// read fails; when `prefix_check` fails, the failure keeps the check's rule (a file that is
// there but of the wrong kind is not an I/O problem), its message "PATH: " + the check's.
ir::Result<std::string> read_bounded(const std::string& path, const ReadCap& cap,
                                     const PrefixCheck& prefix_check = nullptr);

// "4 MiB", "1 GiB", "512 bytes": a cap as the messages print it.
std::string format_size(uint64_t bytes);

} // namespace tierlift::io
