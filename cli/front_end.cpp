#include "front_end.h"

#include <cstdio>

#include <fmt/format.h>

#include "report.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/preprocessor.h"
#include "tierlift/io/output_file.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/profile.h"
#include "tierlift/ir/result_diagnostics.h"

namespace tierlift::cli {

void add_strict_flag(CLI::App* sub, FrontEndOptions& o) {
  sub->add_flag("--strict", o.strict,
                "The documented rules only: reject what the Direct3D runtimes took beyond them "
                "(scalar sources without a replicate swizzle, ps_1_4 texcrd without a mask)");
}

namespace {

// -D NAME[=VALUE] the preprocessor takes: a bad one (NAME not an identifier, VALUE that does
// not lex) is a usage error (exit 2) when the flag is read, not an error of the listing
// (exit 1). The preprocessor itself decides, on an empty listing, so the rule is its own.
std::string define_problem(std::string& word) {
  assembly::ParseOptions options;
  options.defines = split_defines({word});
  options.allow_include = false;
  assembly::ParseResult r = assembly::parse_text("vs_1_1\n", "-D", options);
  for (const ir::Diagnostic& d : r.diags.all())
    if (d.severity == ir::Severity::Error && d.rule == "preprocessor")
      return fmt::format("'{}' is not NAME or NAME=VALUE (NAME an identifier, VALUE tokens of "
                         "assembly)",
                         word);
  return {};
}

} // namespace

void add_front_end_options(CLI::App* sub, FrontEndOptions& o, bool skip_validation_flag,
                           bool json_flag) {
  // allow_extra_args(false): `-I dir file.psh` gives -I one folder, not every word after it.
  sub->add_option("-D,--define", o.defines, "Preprocessor macro NAME or NAME=VALUE (repeatable)")
      ->allow_extra_args(false)
      ->check(CLI::Validator(define_problem, "", "define"));
  sub->add_option("-I,--include-dir", o.include_dirs, "Folder searched by #include (repeatable)")
      ->allow_extra_args(false);
  sub->add_option("--profile", o.profile,
                  "Validate against this profile instead of the listing's version line "
                  "(vs_1_1 vs_2_0 vs_2_x vs_3_0 ps_1_1 ps_1_2 ps_1_3 ps_1_4 ps_2_0 ps_2_x "
                  "ps_3_0, or the fxc targets ps_2_a ps_2_b vs_2_a for the 2.x caps)");
  sub->add_option_function<size_t>(
         "--max-errors", [](const size_t& n) { Report::set_error_limit(n); },
         "Show at most N errors of the listings, then stop (0: all; default 100)")
      ->type_name("N");
  if (json_flag)
    sub->add_flag("--json", o.json,
                  "Print one JSON document on standard output (docs/command-line.md)");
  add_strict_flag(sub, o);
  if (skip_validation_flag)
    sub->add_flag("--skip-validation", o.skip_validation,
                  "Do not apply the profile rules (like fxc /Vd): a fragment that parses is "
                  "enough");
}

ir::Status output_conflict(const std::string& output, const std::vector<std::string>& inputs) {
  return io::refuse_if_input(output, inputs);
}

ir::Status refuse_included(const std::string& output, const LoadedListing& listing) {
  for (const std::string& inc : assembly::included_files(listing.sources))
    if (io::same_file(output, inc))
      return ir::fail(output, "write",
                      fmt::format("{}: refusing to write over {}, which {} #includes{}", output,
                                  inc, listing.sources.files[0].name,
                                  inc == output ? "" : " (the same file)"));
  return ir::ok_status();
}

ir::Result<LoadedListing> load_writing_to(const std::string& path, const FrontEndOptions& options,
                                          const std::string& output, std::string& failed_path) {
  failed_path = path;
  ir::Result<LoadedListing> loaded = load_listing(path, options);
  if (!loaded) return loaded;
  if (ir::Status refused = refuse_included(output, *loaded); !refused) {
    failed_path = output;
    return refused.failure();
  }
  return loaded;
}

ir::Status check_output(const std::string& output, const std::vector<std::string>& inputs,
                        bool json) {
  if (json && output == "-")
    return ir::fail(output, "usage", "-o - and --json both write standard output; give -o a file");
  return output_conflict(output, inputs);
}

std::string write_output(const std::string& path, std::string_view bytes) {
  return io::write_output(path, bytes).message();
}

std::vector<std::pair<std::string, std::string>>
split_defines(const std::vector<std::string>& defines) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& d : defines) {
    auto eq = d.find('=');
    if (eq == std::string::npos)
      out.emplace_back(d, "1");
    else
      out.emplace_back(d.substr(0, eq), d.substr(eq + 1));
  }
  return out;
}

ir::Result<LoadedListing> load_listing(const std::string& path, const FrontEndOptions& options,
                                       const io::ReadCap& cap) {
  LoadedListing out;
  ir::Result<std::string> text = io::read_bounded(path, cap);
  if (!text) return ir::fail(path, "io", text.message());
  // Visual Studio saves listings with a UTF-8 byte-order mark; it is not part of the text.
  if (text->starts_with("\xEF\xBB\xBF")) text->erase(0, 3);
  std::optional<ir::Profile> target;
  std::optional<ir::Caps2x> caps;
  if (!options.profile.empty()) {
    target = ir::parse_profile(options.profile);
    if (auto preset = ir::caps_preset(options.profile)) {
      target = preset->first;
      caps = preset->second;
    }
    if (!target)
      return ir::fail(path, "io",
                      fmt::format("unknown profile '{}' (expected one of vs_1_1 vs_2_0 vs_2_x "
                                  "vs_2_a vs_3_0 ps_1_1 ps_1_2 ps_1_3 ps_1_4 ps_2_0 ps_2_x "
                                  "ps_2_a ps_2_b ps_3_0)",
                                  options.profile));
  }
  assembly::LoadOptions lopts;
  lopts.parse.defines = split_defines(options.defines);
  lopts.parse.include_dirs = options.include_dirs;
  lopts.profile = target;
  lopts.caps = caps;
  lopts.skip_validation = options.skip_validation;
  lopts.strict = options.strict;
  uint32_t file = out.sources.add(path == "-" ? "<stdin>" : path, std::move(*text));
  assembly::Loaded r = assembly::load_listing(file, out.sources, lopts);
  out.form = r.form;
  out.constants = std::move(r.constants);
  ir::add_all(out.diags, r.program.diagnostics());
  if (r.program) out.program = std::move(r.program).value();
  return out;
}

bool check_executable(LoadedListing& listing, std::string_view backend) {
  if (!listing.program) return false;
  ir::Status s = ir::check_executable(*listing.program, backend);
  if (s) return true;
  ir::add_all(listing.diags, s.diagnostics());
  return false;
}

nlohmann::json constants_json(const assembly::ConstantTable& table) {
  static constexpr const char* kSets[] = {"bool", "int4", "float4", "sampler"};
  nlohmann::json out = nlohmann::json::array();
  for (const assembly::NamedConstant& c : table.constants)
    out.push_back({{"name", c.name},
                   {"registers", c.registers()},
                   {"set", kSets[static_cast<int>(c.set)]},
                   {"index", c.index},
                   {"count", c.count},
                   {"type", c.type}});
  return out;
}

} // namespace tierlift::cli
