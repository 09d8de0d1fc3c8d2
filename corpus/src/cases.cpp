#include "tierlift/corpus/cases.h"

#include "version_line.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include <fmt/format.h>

#include "tierlift/assembly/load.h"

namespace tierlift::corpus {
namespace fs = std::filesystem;

uint64_t fnv1a64(std::string_view bytes) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

std::string hex64(uint64_t v) {
  return fmt::format("{:016x}", v);
}

std::string case_id(std::string_view relative, std::string_view bytes) {
  return fmt::format("{}@{}", relative, hex64(fnv1a64(bytes)));
}

bool in_shard(const Case& c, size_t index, size_t count) {
  return count <= 1 || fnv1a64(c.id) % count == index;
}

namespace {

// Discovery reads each file once to hash it; larger files than any listing are hashed on
// their first 64 MiB (the worker refuses them with the reader's own message).
constexpr std::streamsize kHashCap = std::streamsize{64} << 20;

std::optional<std::string> read_prefix(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return std::nullopt;
  // Sized to the file (a buffer of the whole cap per file would cost a page fault per 4 KiB).
  std::error_code ec;
  const uintmax_t size = fs::file_size(p, ec);
  const std::streamsize want = ec ? kHashCap : std::min<std::streamsize>(kHashCap, size);
  std::string bytes(static_cast<size_t>(want), '\0');
  in.read(bytes.data(), want);
  bytes.resize(static_cast<size_t>(in.gcount()));
  return bytes;
}

// Lines of a list file: every non-blank line not starting with '#', trimmed.
std::vector<std::string> list_entries(std::string_view text) {
  std::vector<std::string> out;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t nl = text.find('\n', pos);
    std::string_view line = text.substr(pos, nl == std::string_view::npos ? nl : nl - pos);
    pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back())))
      line.remove_suffix(1);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.front())))
      line.remove_prefix(1);
    if (!line.empty() && line.front() != '#') out.emplace_back(line);
  }
  return out;
}

// A text file whose every entry names something that exists next to it. A listing's lines
// ("ps_2_0", "mov oC0, c0") never all name files, so listings are never taken for lists.
bool is_list_file(const fs::path& file, std::string_view bytes) {
  if (assembly::detect_listing_form(bytes) != assembly::ListingForm::Text) return false;
  std::vector<std::string> entries = list_entries(bytes);
  if (entries.empty()) return false;
  std::error_code ec;
  for (const std::string& e : entries)
    if (!fs::exists(file.parent_path() / e, ec)) return false;
  return true;
}

std::string generic(const fs::path& p) {
  return p.lexically_normal().generic_string();
}

// The name a root contributes to its cases' ids: its own last component ("listings" for
// "../x/listings/"), so that the same tree gives the same ids wherever it lies.
std::string root_name(const fs::path& root) {
  fs::path norm = root.lexically_normal();
  if (!norm.has_filename()) norm = norm.parent_path();
  std::string name = norm.filename().generic_string();
  return name.empty() || name == "." || name == ".." ? std::string("root") : name;
}

struct Collector {
  std::vector<Case> cases;
  std::set<std::string> seen;
  std::set<fs::path> lists_open; // a list that names itself is not read twice

  void add_file(const fs::path& path, const std::string& relative, const std::string& bytes) {
    Case c;
    c.id = case_id(relative, bytes);
    c.path = path.string();
    if (seen.insert(c.id).second) cases.push_back(std::move(c));
  }
};

ir::Status add_root(Collector& col, const fs::path& root, const std::string& prefix);

ir::Status add_folder(Collector& col, const fs::path& dir, const std::string& name) {
  std::error_code ec;
  fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
  if (ec) return ir::fail(dir.string(), "io", fmt::format("{}: {}", dir.string(), ec.message()));
  for (auto end = fs::recursive_directory_iterator(); it != end; it.increment(ec)) {
    if (ec) return ir::fail(dir.string(), "io", fmt::format("{}: {}", dir.string(), ec.message()));
    const fs::path& p = it->path();
    if (p.filename().string().starts_with(".")) {
      if (it->is_directory(ec)) it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file(ec)) continue;
    std::optional<std::string> bytes = read_prefix(p);
    if (!bytes || !looks_like_listing(*bytes)) continue;
    // Lexically: p is dir joined with the entries walked, so no symbolic link or ".." needs
    // resolving (fs::relative canonicalises both paths, a realpath of every component of
    // each, per file).
    col.add_file(p, name + "/" + generic(p.lexically_relative(dir)), *bytes);
  }
  return ir::ok_status();
}

ir::Status add_root(Collector& col, const fs::path& root, const std::string& relative) {
  std::error_code ec;
  if (fs::is_directory(root, ec)) return add_folder(col, root, relative);
  if (!fs::exists(root, ec))
    return ir::fail(root.string(), "io", fmt::format("{}: no such file or folder", root.string()));
  std::optional<std::string> bytes = read_prefix(root);
  if (!bytes) return ir::fail(root.string(), "io", fmt::format("{}: cannot read", root.string()));
  fs::path canonical = fs::weakly_canonical(root, ec);
  if (is_list_file(root, *bytes) && !col.lists_open.contains(canonical)) {
    col.lists_open.insert(canonical);
    for (const std::string& e : list_entries(*bytes)) {
      fs::path target = root.parent_path() / e;
      std::string name = fs::is_directory(target, ec) ? root_name(target) : generic(e);
      if (ir::Status s = add_root(col, target, name); !s) return s;
    }
    return ir::ok_status();
  }
  col.add_file(root, relative, *bytes);
  return ir::ok_status();
}

} // namespace

bool looks_like_listing(std::string_view bytes) {
  switch (assembly::detect_listing_form(bytes)) {
  case assembly::ListingForm::TokenStream:
  case assembly::ListingForm::TokenArray: return true;
  case assembly::ListingForm::Binary:
    // A token stream cut short (not a whole number of DWORDs) is still a shader file, one
    // that must fail its parse stage rather than vanish from the corpus.
    return bytes.size() >= 4 && (static_cast<unsigned char>(bytes[3]) == 0xFF) &&
           static_cast<unsigned char>(bytes[2]) >= 0xFE;
  case assembly::ListingForm::Text: break;
  }
  return version_line_major(bytes).has_value();
}

ir::Result<std::vector<Case>> discover(const std::vector<std::string>& roots) {
  Collector col;
  for (const std::string& r : roots) {
    fs::path root(r);
    std::error_code ec;
    std::string name = fs::is_directory(root, ec) ? root_name(root) : root.filename().string();
    if (ir::Status s = add_root(col, root, name); !s) return s.failure();
  }
  std::sort(col.cases.begin(), col.cases.end(),
            [](const Case& a, const Case& b) { return a.id < b.id; });
  return col.cases;
}

} // namespace tierlift::corpus
