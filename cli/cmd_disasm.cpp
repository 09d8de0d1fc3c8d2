// tierlift disasm FILE: a D3D9 token stream (raw bytes or a C array of hex DWORDs) back
// into the IR, validated, printed as canonical text; the CTAB constant table, when the
// stream has one, heads the text as comments.
#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
#include "tierlift/asm/constant_table.h"
#include "tierlift/asm/printer.h"

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
  sub->add_flag("--json", opts->fe.json, "Print diagnostics (and the CTAB constants) as JSON");
  sub->add_flag("--skip-validation", opts->fe.skip_validation, "Do not apply the profile rules");
  sub->add_option("--profile", opts->fe.profile, "Validate against this profile");
  add_strict_flag(sub, opts->fe);
  set_action(sub, [opts] {
    LoadedListing l = load_listing(opts->file, opts->fe);
    if (l.io_error) {
      fmt::print(stderr, "tierlift: error: {}\n", l.io_message);
      return kExitUsage;
    }
    if (l.form == as::ListingForm::Text) {
      fmt::print(stderr,
                 "{}: error: this is assembly text, not a token stream; `tierlift fmt` prints "
                 "it in canonical form, `tierlift assemble` makes a token stream of it\n",
                 opts->file);
      return kExitInvalid;
    }
    if (opts->fe.json) {
      nlohmann::json j = {{"diagnostics", diagnostics_json(l)}};
      if (l.constants) j["constants"] = constants_json(*l.constants);
      fmt::print(stderr, "{}\n", j.dump(2));
    } else {
      print_diagnostics(l);
    }
    if (!l.program) return kExitInvalid;
    if (l.constants) fmt::print("{}", as::print_constant_table(*l.constants));
    fmt::print("{}", as::print_program(*l.program));
    return kExitOk;
  });
}

} // namespace tierlift::cli
