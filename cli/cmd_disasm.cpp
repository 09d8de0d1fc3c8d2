// tierlift disasm FILE: a D3D9 token stream (raw bytes or a C array of hex DWORDs) back
// into the IR, validated, printed as canonical text; the CTAB constant table, when the
// stream has one, heads the text as comments.
#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
#include "report.h"
#include "tierlift/assembly/constant_table.h"
#include "tierlift/assembly/printer.h"
#include "tierlift/assembly/text_form.h"

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
                "Print one JSON document on standard output, the CTAB constants included "
                "(docs/command-line.md)");
  sub->add_flag("--skip-validation", opts->fe.skip_validation, "Do not apply the profile rules");
  sub->add_option("--profile", opts->fe.profile, "Validate against this profile");
  add_strict_flag(sub, opts->fe);
  set_action(sub, [opts] {
    Report report("disasm", opts->fe.json);
    if (ir::Status out = output_conflict(opts->output, {opts->file}); !out) {
      report.error("io", out.message(), opts->output);
      return report.finish(kExitUsage);
    }
    // The loader reads within the token-file cap, tells a token stream from text by content,
    // validates (unless skipped) and reads the CTAB.
    ir::Result<LoadedListing> loaded = load_listing(opts->file, opts->fe, io::kTokenFileCap);
    if (!loaded) {
      report.error("io", loaded.message(), opts->file);
      return report.finish(kExitUsage);
    }
    LoadedListing& l = *loaded;
    if (l.form == assembly::ListingForm::Text) {
      // Say what it is: an empty file or a broken C array is not "assembly text".
      ir::DiagnosticSink why;
      const std::string what = assembly::describe_text_form(l.sources.files[0].text, why);
      report.error("listing-form",
                   what.empty() ? "this is assembly text, not a token stream; `tierlift fmt` "
                                  "prints it in canonical form, `tierlift assemble` makes a "
                                  "token stream of it"
                                : fmt::format("this is {}, not a token stream", what),
                   opts->file);
      report.diagnostics(why, l.sources);
      return report.finish(kExitInvalid);
    }
    report.diagnostics(l.diags, l.sources);
    report.result()["form"] = assembly::listing_form_name(l.form);
    if (l.constants) report.result()["constants"] = constants_json(*l.constants);
    if (!l.program || l.diags.has_errors()) return report.finish(kExitInvalid);
    std::string text = assembly::print_program(*l.program);
    if (l.constants) text = assembly::print_constant_table(*l.constants) + text;
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
