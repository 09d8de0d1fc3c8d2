// tierlift fmt FILE: the canonical text of a listing (parse → IR → print).
#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
#include "tierlift/asm/printer.h"

namespace tierlift::cli {

void register_fmt_command(CLI::App& app) {
  struct Opts {
    std::string file, output;
    FrontEndOptions fe;
  };
  auto opts = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand("fmt", "Print a listing in canonical form");
  sub->add_option("file", opts->file, "Listing ('-' reads standard input)")->required();
  sub->add_option("-o,--output", opts->output, "Write to this file instead of standard output");
  add_front_end_options(sub, opts->fe, true);
  set_action(sub, [opts] {
    LoadedListing l = load_listing(opts->file, opts->fe);
    if (l.io_error) {
      fmt::print(stderr, "tierlift: error: {}\n", l.io_message);
      return kExitUsage;
    }
    if (opts->fe.json)
      fmt::print(stderr, "{}\n", diagnostics_json(l).dump(2));
    else
      print_diagnostics(l);
    if (!l.program) return kExitInvalid;
    std::string text = as::print_program(*l.program);
    if (opts->output.empty()) {
      fmt::print("{}", text);
      return kExitOk;
    }
    std::string error;
    if (!write_file_atomically(opts->output, text, error)) {
      fmt::print(stderr, "tierlift: error: {}\n", error);
      return kExitUsage;
    }
    return kExitOk;
  });
}

} // namespace tierlift::cli
