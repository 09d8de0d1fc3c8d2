// `tierlift report --stress`: the stress catalogue's flags and run, joined to the report
// command by cmd_report.cpp (which owns -o, --json, -q and --gpu for both).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace tierlift::cli {

struct StressFlags {
  bool stress = false, json = false, quiet = false;
  std::string output, gpu, only;
};

// --stress, --case, --list on the report command.
void add_stress_flags(CLI::App* sub, StressFlags& f);
int run_stress(const StressFlags& f);

} // namespace tierlift::cli
