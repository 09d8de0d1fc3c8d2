#include "tierlift/corpus/output_guard.h"

#include <filesystem>
#include <sys/stat.h>
#include <utility>

#include <fmt/format.h>

namespace tierlift::corpus {

std::vector<std::string> output_files(const std::string& dir) {
  std::vector<std::string> out;
  for (const char* name :
       {"results.jsonl", "results.csv", "failures.csv", "junit.xml", "summary.md", "workers.log"})
    out.push_back((std::filesystem::path(dir) / name).string());
  return out;
}

ir::Status refuse_outputs_among_inputs(const std::string& dir,
                                       std::span<const std::string> inputs) {
  // Only outputs that exist can be an input: a fresh folder costs nothing more.
  std::vector<std::pair<std::string, struct stat>> existing;
  for (const std::string& path : output_files(dir)) {
    struct stat s {};
    if (::stat(path.c_str(), &s) == 0) existing.emplace_back(path, s);
  }
  if (existing.empty()) return ir::ok_status();
  for (const std::string& in : inputs) {
    struct stat s {};
    if (in.empty() || in == "-" || ::stat(in.c_str(), &s) != 0) continue;
    for (const auto& [path, o] : existing)
      if (o.st_dev == s.st_dev && o.st_ino == s.st_ino)
        return ir::fail(in, "write",
                        in == path
                            ? fmt::format("{}: refusing to run: the run reads this file and "
                                          "writes over it (keep it outside the output folder, or "
                                          "give another -o)",
                                          in)
                            : fmt::format("{}: refusing to run: the run reads this file and writes "
                                          "over it as {} (the same file; keep it outside the "
                                          "output folder, or give another -o)",
                                          in, path));
  }
  return ir::ok_status();
}

ir::Status refuse_foreign_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec) || fs::exists(fs::path(dir) / "results.jsonl", ec))
    return ir::ok_status(); // new, or an earlier run's (a path that is no folder fails later)
  if (fs::directory_iterator(dir, ec) == fs::directory_iterator()) return ir::ok_status();
  return ir::fail(dir, "write",
                  fmt::format("{}: refusing to write the results there: the folder holds other "
                              "files and no results.jsonl, and the run would replace any of "
                              "{} (give a new or empty folder)",
                              dir, "results.csv, failures.csv, junit.xml, summary.md"));
}

} // namespace tierlift::corpus
