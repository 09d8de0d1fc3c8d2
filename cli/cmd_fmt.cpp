// tierlift fmt FILE: the canonical text of a listing (parse → IR → print), with its
// comments and blank-line structure kept.
#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
#include "report.h"
#include "tierlift/assembly/preprocessor.h"
#include "tierlift/assembly/printer.h"

namespace tierlift::cli {
namespace {

// One error at the first directive or -D macro use of a text listing (none otherwise):
// fmt prints the parsed program, where #include is inlined, macros are expanded and the
// #if branch not taken is gone, so it refuses rather than lose source.
ir::DiagnosticSink preprocessor_kept(const LoadedListing& l, const FrontEndOptions& fe) {
  ir::DiagnosticSink out;
  if (l.form != assembly::ListingForm::Text) return out; // a C array's #if 0 is not the listing's
  assembly::ParseOptions po;
  po.defines = split_defines(fe.defines);
  if (std::optional<assembly::PreprocessorUse> use =
          assembly::first_preprocessor_use(0, l.sources, po))
    out.error(use->loc, "fmt-preprocessor",
              fmt::format("fmt cannot keep {}: it prints the parsed program, in which #include "
                          "is inlined, macros are expanded and the #if branch not taken is "
                          "gone; format a listing without directives or -D macros (an "
                          "included file can be formatted on its own), or keep this one as "
                          "it is",
                          use->what));
  return out;
}

} // namespace

void register_fmt_command(CLI::App& app) {
  struct Opts {
    std::string file, output = "-";
    FrontEndOptions fe;
  };
  auto opts = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand("fmt", "Print a listing in canonical form");
  sub->add_option("file", opts->file, "Listing ('-' reads standard input)")->required();
  sub->add_option("-o,--output", opts->output, "Output file ('-': standard output)")
      ->capture_default_str();
  add_front_end_options(sub, opts->fe, true);
  set_action(sub, [opts] {
    Report report("fmt", opts->fe.json);
    if (ir::Status out = output_conflict(opts->output, {opts->file}); !out) {
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
    report.diagnostics(l.diags, l.sources);
    if (!l.program) return report.finish(kExitInvalid);
    // The program has no directives and no macros left: printing it would drop them.
    if (ir::DiagnosticSink kept = preprocessor_kept(l, opts->fe); kept.has_errors()) {
      report.diagnostics(kept, l.sources);
      return report.finish(kExitInvalid);
    }
    // The listing's comments and paragraphs stay; a formatter must not delete them.
    std::string text =
        assembly::print_program_with_comments(*l.program, l.sources.files[0].text, 0);
    if (opts->output == "-") {
      report.output("text", text);
      return report.finish(kExitOk);
    }
    if (std::string error = write_output(opts->output, text); !error.empty()) {
      report.error("io", error, opts->output);
      return report.finish(kExitUsage);
    }
    report.result()["written"] = opts->output;
    return report.finish(kExitOk);
  });
}

} // namespace tierlift::cli
