// Runs the built `tierlift` binary in a shell and captures its exit code and output.
#pragma once

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace tierlift::test {

struct CliResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// `args` is appended to the binary's path as shell text (quote it yourself).
inline CliResult run_cli(const std::string& args, const std::string& stdin_text = "") {
  // One folder per process and call: ctest runs tests of this binary in parallel.
  static std::atomic<int> counter{0};
  auto dir = std::filesystem::temp_directory_path() /
             ("tierlift_cli_run_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  std::filesystem::create_directories(dir);
  auto in = dir / "stdin.txt", out = dir / "stdout.txt", err = dir / "stderr.txt";
  { std::ofstream(in, std::ios::binary) << stdin_text; }
  std::string cmd = std::string(TIERLIFT_CLI_PATH) + " " + args + " <" + in.string() + " >" +
                    out.string() + " 2>" + err.string();
  int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_all(out);
  r.err = read_all(err);
  std::filesystem::remove_all(dir);
  return r;
}

inline std::string listing(const std::string& name) {
  return std::string(TIERLIFT_SOURCE_DIR) + "/listings/gpugems21/" + name;
}

} // namespace tierlift::test
