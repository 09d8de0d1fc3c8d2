#include "bench_inputs.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace tierlift::bench {
namespace {

void add_folder(std::vector<ListingText>& out, const std::filesystem::path& dir, bool recurse) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return;
  std::vector<std::filesystem::path> files;
  auto take = [&](const std::filesystem::directory_entry& e) {
    auto ext = e.path().extension();
    if (e.is_regular_file() && (ext == ".vsh" || ext == ".psh")) files.push_back(e.path());
  };
  if (recurse)
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) take(e);
  else
    for (const auto& e : std::filesystem::directory_iterator(dir)) take(e);
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    out.push_back({f.filename().string(), std::string(std::istreambuf_iterator<char>(in),
                                                      std::istreambuf_iterator<char>())});
  }
}

} // namespace

const std::vector<ListingText>& all_listings() {
  static const std::vector<ListingText> listings = [] {
    std::vector<ListingText> out;
    add_folder(out, std::filesystem::path(TIERLIFT_SOURCE_DIR) / "listings", true);
    add_folder(out, std::filesystem::path(TIERLIFT_SHARED_DIR) / "corpus", false);
    return out;
  }();
  return listings;
}

size_t total_bytes(const std::vector<ListingText>& listings) {
  size_t n = 0;
  for (const auto& l : listings) n += l.text.size();
  return n;
}

} // namespace tierlift::bench
