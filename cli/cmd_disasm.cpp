// tierlift disasm FILE: a D3D9 token stream (raw bytes or a C array of hex DWORDs) back
// into the IR, validated, printed as canonical text.
#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
#include "report.h"
#include "tierlift/asm/bytecode.h"
#include "tierlift/asm/printer.h"
#include "tierlift/asm/validator.h"
#include "tierlift/ir/profile.h"

namespace tierlift::cli {

void register_disasm_command(CLI::App& app) {
  struct Opts {
    std::string file, output = "-";
    FrontEndOptions fe;
  };
  auto opts = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand("disasm", "Disassemble a D3D9 token stream");
  sub->add_option("file", opts->file, "Token stream: raw little-endian or a C array ('-' = stdin)")
      ->required();
  sub->add_option("-o,--output", opts->output, "Output file ('-': standard output)")
      ->capture_default_str();
  sub->add_flag("--json", opts->fe.json,
                "Print one JSON document on standard output (docs/command-line.md)");
  sub->add_flag("--skip-validation", opts->fe.skip_validation, "Do not apply the profile rules");
  sub->add_option("--profile", opts->fe.profile, "Validate against this profile");
  set_action(sub, [opts] {
    Report report("disasm", opts->fe.json);
    if (std::string why = output_conflict(opts->output, {opts->file}); !why.empty()) {
      report.error("io", why, opts->output);
      return report.finish(kExitUsage);
    }
    std::optional<ir::Profile> target;
    if (!opts->fe.profile.empty()) {
      target = ir::parse_profile(opts->fe.profile);
      if (!target) {
        report.error("usage", fmt::format("unknown profile '{}'", opts->fe.profile));
        return report.finish(kExitUsage);
      }
    }
    LoadedListing l;
    std::string error;
    auto bytes = read_file(opts->file, io::kTokenFileCap, error);
    if (!bytes) {
      report.error("io", error, opts->file);
      return report.finish(kExitUsage);
    }
    // A C-array file is text: keep it so that its diagnostics can quote the line.
    bool is_text = bytes->find('\0') == std::string::npos;
    uint32_t file =
        l.sources.add(opts->file == "-" ? "<stdin>" : opts->file, is_text ? *bytes : "");
    std::optional<ir::Program> program;
    if (auto tokens = as::read_token_file(*bytes, l.diags, file))
      program = as::disassemble(*tokens, l.diags, file);
    if (program && !opts->fe.skip_validation &&
        !as::validate(*program, target.value_or(program->profile), l.diags))
      program.reset();
    report.diagnostics(l.diags, l.sources);
    if (!program) return report.finish(kExitInvalid);
    std::string text = as::print_program(*program);
    if (opts->output == "-") {
      report.output("text", text);
      return report.finish(kExitOk);
    }
    if (std::string err = write_output(opts->output, text); !err.empty()) {
      report.error("io", err, opts->output);
      return report.finish(kExitUsage);
    }
    report.result()["written"] = opts->output;
    return report.finish(kExitOk);
  });
}

} // namespace tierlift::cli
