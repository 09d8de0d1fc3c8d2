// What every suite that walks our listings needs: read a file whole, and list the .vsh/.psh
// files of a folder in a stable order. The folders themselves come from TIERLIFT_SOURCE_DIR
// (listings/) and TIERLIFT_SHARED_DIR (corpus/; tests skip when it is absent).
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace tierlift::test {

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Sorted .vsh/.psh files of `dir` (of its subfolders too when `recursive`); empty when the
// folder does not exist.
inline std::vector<std::filesystem::path> listings_in(const std::filesystem::path& dir,
                                                      bool recursive = false) {
  namespace fs = std::filesystem;
  std::vector<fs::path> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  auto take = [&](const fs::directory_entry& e) {
    auto ext = e.path().extension();
    if (ext == ".vsh" || ext == ".psh") out.push_back(e.path());
  };
  if (recursive)
    for (const auto& e : fs::recursive_directory_iterator(dir, ec)) take(e);
  else
    for (const auto& e : fs::directory_iterator(dir, ec)) take(e);
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace tierlift::test
