// Source positions and the files they point into.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tierlift::ir {

// 1-based line and column; line 0 means "no position" (e.g. a program read from bytecode).
struct SourceLoc {
  uint32_t file = 0; // index into SourceManager::files
  uint32_t line = 0;
  uint32_t col = 0;
  uint32_t length = 0; // characters the caret line underlines (at least 1 is shown)
  // A position in a token stream (a program read from bytecode): the byte offset of the
  // token, shown as "shader.bin:+0x1c:"; -1 = none.
  int64_t byte_offset = -1;
  bool valid() const { return line != 0; }
  bool has_offset() const { return byte_offset >= 0; }
  static SourceLoc at_byte(uint32_t file, size_t offset) {
    SourceLoc l;
    l.file = file;
    l.byte_offset = static_cast<int64_t>(offset);
    return l;
  }
};

struct SourceFile {
  std::string name; // as given on the command line ("-" shows as "<stdin>")
  std::string text;
  // Read by the preprocessor's #include (name: the path it opened): an input of the command
  // as much as the listing is (assembly::included_files).
  bool included = false;
};

// Owns every file a program was read from (the listing and its #includes), so that
// diagnostics can quote the offending line.
struct SourceManager {
  std::vector<SourceFile> files;
  uint32_t add(std::string name, std::string text) {
    files.push_back({std::move(name), std::move(text)});
    return static_cast<uint32_t>(files.size() - 1);
  }
  // The text of a 1-based line, without its newline; empty when out of range.
  std::string line_text(uint32_t file, uint32_t line) const;
};

} // namespace tierlift::ir
