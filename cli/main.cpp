// tierlift: thin command line over the libraries. Flags are parsed here; the work is done
// by the modules (assembly, runtime, codegen).
#include <fmt/format.h>

#include <cstdio>
#include <string_view>
#include <system_error>
#include <unistd.h>

#include "commands.h"
#include "report.h"
#include "tierlift/crash/crash.h"
#include "tierlift/io/std_streams.h"

namespace {

constexpr const char* kExamples = R"(Examples:
  tierlift check listings/gpugems21/*.vsh listings/gpugems21/*.psh
  tierlift check --profile ps_1_1 shader.psh      check against another profile
  tierlift fmt shader.vsh                          canonical text
  tierlift assemble shader.psh -o shader.bin       Direct3D 9 token stream
  tierlift disasm shader.bin                       token stream (raw or C array) back to text
  tierlift listings                                check and print the built-in article listings
  tierlift report --quick -o report-out             glow error against run time, Pareto plot
  tierlift spirv blur.vsh --pair blur.psh --explain   SPIR-V, pruned against the other stage
  tierlift run --vs blur.vsh --ps blur.psh --texture s0=builtin:noise:64x64 -o out.pfm
  tierlift diff a.png b.pfm --tolerance 0.004 --heatmap d.png   how far two images are apart
Conventions (every command; docs/command-line.md):
  '-' as an input reads standard input; -o - writes standard output (one-file outputs).
  An output that is one of the inputs is refused (exit 2); -o onto a symbolic link writes
  the file it points to; onto a FIFO or device writes straight through.
  -D NAME[=VALUE] and -I DIR take one value each and may be repeated.
  --json prints one JSON document on standard output: {command, exit_code, ok,
  diagnostics, result}, errors included.
  --backend cpu | vulkan | both (cpu and vulkan) | all (every way: glow adds analytic).
Exit codes: 0 ok, 1 invalid input or disagreement, 2 usage or I/O error.
)";

// The subcommand a failed parse was meant for: the first argument that names one (CLI11
// stops at the error, so the parsed state may not say). "tierlift" when none does.
std::string intended_command(const CLI::App& app, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--") break;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_name() == arg) return sub->get_name();
  }
  return "tierlift";
}

// --json anywhere before "--" asks for the JSON document, even when the parse failed.
bool json_requested(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--") return false;
    if (arg == "--json") return true;
  }
  return false;
}

// Parses the flags and runs the command; main() wraps it.
int run_main(int argc, char** argv) {
  CLI::App app{"tierlift: lift Direct3D shader assembly (vs/ps 1.x-3.0; 2.x/3.0 front end only) "
               "onto Vulkan"};
  app.set_version_flag("-V,--version", std::string("tierlift ") + TIERLIFT_VERSION);
  app.footer(kExamples);
  app.require_subcommand(0, 1);
  tierlift::cli::register_check_command(app);
  tierlift::cli::register_fmt_command(app);
  tierlift::cli::register_assemble_command(app);
  tierlift::cli::register_disasm_command(app);
  tierlift::cli::register_listings_command(app);
  tierlift::cli::register_spirv_command(app);
  tierlift::cli::register_run_command(app);
  tierlift::cli::register_glow_command(app);
  tierlift::cli::register_report_command(app);
  tierlift::cli::register_glsl_command(app);
  tierlift::cli::register_test_command(app);
  tierlift::cli::register_generate_command(app);
  tierlift::cli::register_diff_command(app);
  tierlift::cli::refuse_empty_outputs(app);
  // A crash (a driver's, most likely) says what was running instead of a bare exit 139.
  tierlift::crash::install_handler(intended_command(app, argc, argv), json_requested(argc, argv));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // An unknown flag, a missing value, a bad choice: with --json the same one document
    // every other error gives (docs/command-line.md), the usage error as a diagnostic.
    if (json_requested(argc, argv)) {
      tierlift::cli::Report report(intended_command(app, argc, argv), true);
      report.error("usage", e.what());
      return report.finish(tierlift::cli::kExitUsage);
    }
    app.exit(e);
    return tierlift::cli::kExitUsage;
  }
  return tierlift::cli::run_selected(app);
}

} // namespace

int main(int argc, char** argv) {
  // Standard output is checked like every output: a closed or full one is exit 2.
  tierlift::io::guard_standard_streams();
  tierlift::io::check_stdout_at_exit("tierlift");
  try {
    return run_main(argc, argv);
  } catch (const std::system_error& e) {
    // fmt::print throws when standard output cannot take the text (a full disk, a closed
    // descriptor); std::filesystem throws the same kind. Either is an I/O error, said once.
    const std::string why = tierlift::io::flush_stdout();
    fmt::print(stderr, "tierlift: error: {}\n", why.empty() ? std::string(e.what()) : why);
    if (why.empty()) return tierlift::cli::kExitUsage;
    std::fflush(stderr);
    ::_exit(tierlift::cli::kExitUsage); // the exit-time check would say it a second time
  }
}
