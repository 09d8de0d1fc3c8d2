#include "tierlift/io/output_folder.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "temp_registry.h"
#include "tierlift/io/output_file.h"

namespace tierlift::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kManifestHead =
    "# tierlift: the files the last run wrote into this folder; the next run of the same kind "
    "replaces them and removes those it does not write again. Other files are left alone.\n";

bool plain_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}

// The names a manifest lists (only plain file names: a damaged manifest cannot point
// outside the folder).
std::vector<std::string> read_manifest(const fs::path& path) {
  std::vector<std::string> names;
  std::ifstream in(path, std::ios::binary);
  for (std::string line; std::getline(in, line);)
    if (!line.starts_with('#') && plain_name(line)) names.push_back(line);
  return names;
}

bool is_folder_not_link(const fs::path& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

} // namespace

std::string output_manifest_name(const std::string& tag) {
  return ".tierlift-written-" + tag;
}

OutputFolder::OutputFolder(std::string dir, std::vector<std::string> inputs, std::string tag)
    : dir_(std::move(dir)), tag_(std::move(tag)), inputs_(std::move(inputs)) {
  if (dir_.empty() || dir_ == "-") {
    fail("-o names a folder here; '-' or nothing is not one");
    return;
  }
  std::error_code ec;
  const fs::path target = fs::path(dir_);
  std::string pattern;
  if (fs::exists(target, ec)) {
    if (!fs::is_directory(target, ec)) {
      fail(fmt::format("{}: exists and is not a folder", dir_));
      return;
    }
    dir_existed_ = true;
    // Inside DIR (a link to a folder followed): renames then stay on one file system.
    pattern = (fs::canonical(target, ec) / ".tierlift-tmpXXXXXX").string();
    if (ec) pattern = (target / ".tierlift-tmpXXXXXX").string();
  } else {
    fs::path full = fs::absolute(target, ec).lexically_normal();
    if (full.filename().empty()) full = full.parent_path(); // "out/"
    fs::path nearest = full.parent_path();
    while (!nearest.empty() && !fs::exists(nearest, ec) && nearest != nearest.root_path())
      nearest = nearest.parent_path();
    if (!fs::is_directory(nearest, ec)) {
      fail(fmt::format("{}: cannot make the folder: {} is not a folder", dir_, nearest.string()));
      return;
    }
    // fmt::format for the GCC 12 -Wrestrict false positive (output_file.cpp says more).
    pattern = (nearest / fmt::format(".{}.tmpXXXXXX", full.filename().string())).string();
  }
  int err = 0;
  slot_ = detail::create_registered_temp_dir(pattern, &err);
  if (slot_ < 0) {
    fail(fmt::format("{}: cannot make a temporary folder ({}): {}", dir_,
                     fs::path(pattern).parent_path().string(), std::strerror(err)));
    return;
  }
  temp_ = detail::registered_temp_name(slot_);
}

OutputFolder::~OutputFolder() {
  if (slot_ >= 0) detail::remove_registered_temp(slot_, true);
}

ir::Failure OutputFolder::fail(std::string message) {
  if (error_.empty()) error_ = std::move(message);
  return status().failure();
}

ir::Status OutputFolder::status() const {
  if (error_.empty()) return ir::ok_status();
  return ir::fail(dir_, "write", error_);
}

std::string OutputFolder::final_path(const std::string& name) const {
  return (fs::path(dir_) / name).string();
}

ir::Result<std::string> OutputFolder::path(const std::string& name) {
  if (!error_.empty()) return status().failure();
  if (!plain_name(name) || name.starts_with(".tierlift-"))
    return fail(fmt::format("{}: '{}' is not a plain file name", dir_, name));
  const std::string final = final_path(name);
  if (ir::Status refused = refuse_if_input(final, inputs_); !refused)
    return fail(refused.message());
  if (is_folder_not_link(final))
    return fail(fmt::format("{}: cannot write: it is a folder", final));
  if (std::find(names_.begin(), names_.end(), name) == names_.end()) names_.push_back(name);
  return (fs::path(temp_) / name).string();
}

ir::Result<std::vector<std::string>> OutputFolder::commit() {
  if (!error_.empty()) return status().failure();
  std::error_code ec;
  const fs::path temp(temp_);
  for (const std::string& name : names_)
    if (!fs::is_regular_file(temp / name, ec))
      return fail(fmt::format("{}: {} was never written", dir_, name));
  std::string manifest = kManifestHead;
  for (const std::string& name : names_) manifest += name + "\n";
  const std::string manifest_name = output_manifest_name(tag_);
  if (ir::Status s = write_output((temp / manifest_name).string(), manifest); !s)
    return fail(s.message());

  std::vector<std::string> finals;
  for (const std::string& name : names_) finals.push_back(final_path(name));
  detail::SignalsBlocked blocked; // from here to the end, as one step for an interrupt
  if (!dir_existed_) {
    const fs::path full = fs::absolute(fs::path(dir_), ec).lexically_normal();
    const fs::path parent = (full.filename().empty() ? full.parent_path() : full).parent_path();
    fs::create_directories(parent, ec);
    if (ec) return fail(fmt::format("{}: cannot make its folder: {}", dir_, ec.message()));
    int err = 0;
    if (!detail::rename_registered_temp(slot_, dir_, &err))
      return fail(fmt::format("{}: cannot move the finished folder into place: {}", dir_,
                              std::strerror(err)));
    slot_ = -1;
    return finals;
  }
  const fs::path real = temp.parent_path();
  const std::vector<std::string> before = read_manifest(real / manifest_name);
  for (const std::string& name : names_)
    if (::rename((temp / name).c_str(), (real / name).c_str()) != 0)
      return fail(
          fmt::format("{}: cannot move {} into place: {}", dir_, name, std::strerror(errno)));
  if (::rename((temp / manifest_name).c_str(), (real / manifest_name).c_str()) != 0)
    return fail(fmt::format("{}: cannot move {} into place: {}", dir_, manifest_name,
                            std::strerror(errno)));
  // What the last run wrote and this one did not: stale, unless it is one of the inputs.
  for (const std::string& old : before) {
    if (std::find(names_.begin(), names_.end(), old) != names_.end()) continue;
    const fs::path p = real / old;
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !(S_ISREG(st.st_mode) || S_ISLNK(st.st_mode))) continue;
    if (!refuse_if_input(p.string(), inputs_)) continue;
    ::unlink(p.c_str());
  }
  detail::remove_registered_temp(slot_, true);
  slot_ = -1;
  return finals;
}

} // namespace tierlift::io
