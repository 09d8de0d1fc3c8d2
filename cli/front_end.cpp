#include "front_end.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include <fmt/format.h>
#include <unistd.h>

#include "tierlift/ir/profile.h"

namespace tierlift::cli {

void add_strict_flag(CLI::App* sub, FrontEndOptions& o) {
  sub->add_flag("--strict", o.strict,
                "The documented rules only: reject what the Direct3D runtimes took beyond them "
                "(scalar sources without a replicate swizzle, ps_1_4 texcrd without a mask)");
}

void add_front_end_options(CLI::App* sub, FrontEndOptions& o, bool skip_validation_flag) {
  sub->add_option("-D,--define", o.defines, "Preprocessor macro NAME or NAME=VALUE");
  sub->add_option("-I,--include-dir", o.include_dirs, "Folder searched by #include");
  sub->add_option("--profile", o.profile,
                  "Validate against this profile instead of the listing's version line "
                  "(vs_1_1 vs_2_0 ps_1_1 ps_1_2 ps_1_3 ps_1_4 ps_2_0)");
  sub->add_flag("--json", o.json, "Print diagnostics as JSON on standard output");
  add_strict_flag(sub, o);
  if (skip_validation_flag)
    sub->add_flag("--skip-validation", o.skip_validation,
                  "Do not apply the profile rules (like fxc /Vd): a fragment that parses is "
                  "enough");
}

std::optional<std::string> read_file(const std::string& path, std::string& error) {
  if (path == "-") {
    std::ostringstream ss;
    ss << std::cin.rdbuf();
    return ss.str();
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    error = fmt::format("cannot read '{}': it is a directory", path);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = fmt::format("cannot read '{}': {}", path, std::strerror(errno));
    return std::nullopt;
  }
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) {
    error = fmt::format("cannot read '{}': read error", path);
    return std::nullopt;
  }
  return data;
}

bool write_file_atomically(const std::string& path, std::string_view bytes, std::string& error) {
  namespace fs = std::filesystem;
  fs::path target(path);
  fs::path tmp = target;
  tmp += fmt::format(".tmp-{}", static_cast<long>(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      error = fmt::format("cannot write '{}': {}", path, std::strerror(errno));
      return false;
    }
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      error = fmt::format("cannot write '{}': write failed", path);
      std::error_code ec;
      fs::remove(tmp, ec);
      return false;
    }
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    error = fmt::format("cannot write '{}': {}", path, ec.message());
    fs::remove(tmp, ec);
    return false;
  }
  return true;
}

LoadedListing load_listing(const std::string& path, const FrontEndOptions& options) {
  LoadedListing out;
  std::string error;
  auto text = read_file(path, error);
  if (!text) {
    out.io_error = true;
    out.io_message = error;
    return out;
  }
  std::optional<ir::Profile> target;
  if (!options.profile.empty()) {
    target = ir::parse_profile(options.profile);
    if (!target) {
      out.io_error = true;
      out.io_message = fmt::format("unknown profile '{}' (expected one of vs_1_1 vs_2_0 ps_1_1 "
                                   "ps_1_2 ps_1_3 ps_1_4 ps_2_0)",
                                   options.profile);
      return out;
    }
  }
  as::LoadOptions lopts;
  for (const std::string& d : options.defines) {
    auto eq = d.find('=');
    if (eq == std::string::npos)
      lopts.parse.defines.emplace_back(d, "1");
    else
      lopts.parse.defines.emplace_back(d.substr(0, eq), d.substr(eq + 1));
  }
  lopts.parse.include_dirs = options.include_dirs;
  lopts.profile = target;
  lopts.skip_validation = options.skip_validation;
  lopts.strict = options.strict;
  uint32_t file = out.sources.add(path == "-" ? "<stdin>" : path, std::move(*text));
  as::LoadResult r = as::load_listing(file, out.sources, out.diags, lopts);
  out.form = r.form;
  out.constants = std::move(r.constants);
  out.program = std::move(r.program);
  return out;
}

nlohmann::json diagnostics_json(const LoadedListing& listing) {
  return nlohmann::json::parse(ir::render_json(listing.diags, listing.sources));
}

nlohmann::json constants_json(const as::ConstantTable& table) {
  static constexpr const char* kSets[] = {"bool", "int4", "float4", "sampler"};
  nlohmann::json out = nlohmann::json::array();
  for (const as::NamedConstant& c : table.constants)
    out.push_back({{"name", c.name},
                   {"registers", c.registers()},
                   {"set", kSets[static_cast<int>(c.set)]},
                   {"index", c.index},
                   {"count", c.count},
                   {"type", c.type}});
  return out;
}

void print_diagnostics(const LoadedListing& listing) {
  std::string text = ir::render_text(listing.diags, listing.sources);
  std::fputs(text.c_str(), stderr);
}

} // namespace tierlift::cli
