// The subcommands of `tierlift`. Each register_* adds one subcommand to the app and binds
// its action; main() runs the action of the subcommand that was given.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace tierlift::cli {

// Exit codes shared by every subcommand.
inline constexpr int kExitOk = 0;
inline constexpr int kExitInvalid = 1; // the input is wrong (diagnostics say why)
inline constexpr int kExitUsage = 2;   // bad flags, unreadable or unwritable files

// Binds `action` to `sub`; its return value becomes the exit code.
void set_action(CLI::App* sub, std::function<int()> action);
// Runs the action of the parsed subcommand (kExitUsage with a message when none was given).
int run_selected(CLI::App& app);

void register_check_command(CLI::App& app);
void register_fmt_command(CLI::App& app);
void register_assemble_command(CLI::App& app);
void register_disasm_command(CLI::App& app);
void register_listings_command(CLI::App& app);
void register_run_command(CLI::App& app);
void register_spirv_command(CLI::App& app);
void register_glow_command(CLI::App& app);
void register_report_command(CLI::App& app); // report, report --stress
void register_glsl_command(CLI::App& app);
void register_test_command(CLI::App& app); // test, test merge
void register_generate_command(CLI::App& app);
void register_diff_command(CLI::App& app);
// -o "" on every subcommand is a usage error, not "no output" (registered commands first).
void refuse_empty_outputs(CLI::App& app);

} // namespace tierlift::cli
