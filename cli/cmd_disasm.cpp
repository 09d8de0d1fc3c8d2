// tierlift disasm FILE: a D3D9 token stream (raw bytes or a C array of hex DWORDs) back
// into the IR, validated, printed as canonical text.
#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
#include "tierlift/asm/bytecode.h"
#include "tierlift/asm/printer.h"
#include "tierlift/asm/validator.h"
#include "tierlift/ir/profile.h"

namespace tierlift::cli {

void register_disasm_command(CLI::App& app) {
  struct Opts {
    std::string file;
    FrontEndOptions fe;
  };
  auto opts = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand("disasm", "Disassemble a D3D9 token stream");
  sub->add_option("file", opts->file, "Token stream: raw little-endian or a C array ('-' = stdin)")
      ->required();
  sub->add_flag("--json", opts->fe.json, "Print diagnostics as JSON");
  sub->add_flag("--skip-validation", opts->fe.skip_validation, "Do not apply the profile rules");
  sub->add_option("--profile", opts->fe.profile, "Validate against this profile");
  set_action(sub, [opts] {
    LoadedListing l;
    std::string error;
    auto bytes = read_file(opts->file, error);
    if (!bytes) {
      fmt::print(stderr, "tierlift: error: {}\n", error);
      return kExitUsage;
    }
    // A C-array file is text: keep it so that its diagnostics can quote the line.
    bool is_text = bytes->find('\0') == std::string::npos;
    uint32_t file =
        l.sources.add(opts->file == "-" ? "<stdin>" : opts->file, is_text ? *bytes : "");
    std::optional<ir::Program> program;
    if (auto tokens = as::read_token_file(*bytes, l.diags, file))
      program = as::disassemble(*tokens, l.diags, file);
    if (program && !opts->fe.skip_validation) {
      ir::Profile target = program->profile;
      if (!opts->fe.profile.empty()) {
        auto p = ir::parse_profile(opts->fe.profile);
        if (!p) {
          fmt::print(stderr, "tierlift: error: unknown profile '{}'\n", opts->fe.profile);
          return kExitUsage;
        }
        target = *p;
      }
      if (!as::validate(*program, target, l.diags)) program.reset();
    }
    if (opts->fe.json)
      fmt::print(stderr, "{}\n", diagnostics_json(l).dump(2));
    else
      print_diagnostics(l);
    if (!program) return kExitInvalid;
    fmt::print("{}", as::print_program(*program));
    return kExitOk;
  });
}

} // namespace tierlift::cli
