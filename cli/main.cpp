// tierlift: thin command line over the libraries. Flags are parsed here; the work is done
// by the modules (asm_parser, runtime, codegen).
#include <fmt/format.h>

#include "commands.h"

namespace {

constexpr const char* kExamples = R"(Examples:
  tierlift check listings/gpugems21/*.vsh listings/gpugems21/*.psh
  tierlift check --profile ps_1_1 shader.psh      check against another profile
  tierlift fmt shader.vsh                          canonical text
  tierlift assemble shader.psh -o shader.bin       Direct3D 9 token stream
  tierlift disasm shader.bin                       token stream (raw or C array) back to text
  tierlift listings                                check and print the built-in article listings
  tierlift spirv blur.vsh --pair blur.psh --explain   SPIR-V, pruned against the other stage
  tierlift run --vs blur.vsh --ps blur.psh --texture s0=builtin:noise:64x64 -o out.pfm
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

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"tierlift: lift Direct3D shader assembly (vs/ps 1.x-2.0) onto Vulkan"};
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return tierlift::cli::kExitUsage;
  }
  return tierlift::cli::run_selected(app);
}
