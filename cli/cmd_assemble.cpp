// tierlift assemble FILE -o OUT: the Direct3D 9 token stream of a listing, as raw
// little-endian DWORDs or as a C array.
#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
#include "report.h"
#include "tierlift/assembly/bytecode.h"

namespace tierlift::cli {
namespace {

std::string c_array(const std::vector<uint32_t>& tokens, const std::string& name) {
  std::string out = fmt::format("const unsigned int {}[{}] = {{\n", name, tokens.size());
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (i % 6 == 0) out += "   ";
    out += fmt::format(" 0x{:08x}{}", tokens[i], i + 1 < tokens.size() ? "," : "");
    if (i % 6 == 5 || i + 1 == tokens.size()) out += "\n";
  }
  return out + "};\n";
}

} // namespace

void register_assemble_command(CLI::App& app) {
  struct Opts {
    std::string file, output, c_name;
    bool c_array = false;
    FrontEndOptions fe;
  };
  auto opts = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand("assemble", "Assemble a listing into a D3D9 token stream");
  sub->add_option("file", opts->file, "Listing ('-' reads standard input)")->required();
  sub->add_option("-o,--output", opts->output, "Output file ('-': standard output)")->required();
  sub->add_flag("--c-array", opts->c_array, "Write a C array of hex DWORDs instead of raw bytes");
  sub->add_option("--c-name", opts->c_name, "Name of the C array")->default_val("g_shader");
  add_front_end_options(sub, opts->fe, true);
  set_action(sub, [opts] {
    Report report("assemble", opts->fe.json);
    if (ir::Status out = check_output(opts->output, {opts->file}, opts->fe.json); !out) {
      report.error("io", out.message(), opts->output);
      return report.finish(kExitUsage);
    }
    std::string failed;
    ir::Result<LoadedListing> loaded = load_writing_to(opts->file, opts->fe, opts->output, failed);
    if (!loaded) {
      report.error("io", loaded.message(), failed);
      return report.finish(kExitUsage);
    }
    LoadedListing& l = *loaded;
    // The checked form: a field the token stream cannot carry is an error, not truncated.
    std::optional<std::vector<uint32_t>> tokens;
    if (l.program) tokens = assembly::assemble(*l.program, l.diags);
    report.diagnostics(l.diags, l.sources);
    if (!tokens) return report.finish(kExitInvalid);
    std::string bytes =
        opts->c_array ? c_array(*tokens, opts->c_name) : assembly::tokens_to_bytes(*tokens);
    if (std::string error = write_output(opts->output, bytes); !error.empty()) {
      report.error("io", error, opts->output);
      return report.finish(kExitUsage);
    }
    report.result()["written"] = opts->output;
    report.result()["tokens"] = tokens->size();
    return report.finish(kExitOk);
  });
}

} // namespace tierlift::cli
