// A test fixture for running the built `tierlift` binary: a fresh temporary folder per test
// (removed afterwards), the two ways the tests run the CLI, and a whole-file reader for what
// it wrote there.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace tierlift::cli_test {

class CliFixture : public ::testing::Test {
protected:
  void SetUp() override {
    namespace fs = std::filesystem;
    // The CLI is built with the tests; its absence is a broken build, never a skip.
    ASSERT_TRUE(fs::exists(TIERLIFT_CLI_PATH)) << "tierlift not built: " << TIERLIFT_CLI_PATH;
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::temp_directory_path() /
          ("tierlift_" + std::string(info->test_suite_name()) + "_" +
           std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override {
    if (!dir.empty()) std::filesystem::remove_all(dir);
  }
  // `tierlift ARGS` with stdout and stderr together in out_file; the exit status (-1: killed).
  static int run_cli(const std::string& args, const std::filesystem::path& out_file) {
    return exit_status(std::string(TIERLIFT_CLI_PATH) + " " + args + " > " + out_file.string() +
                       " 2>&1");
  }
  // The same with stdout and stderr apart, read back into out and err; `prefix` goes before
  // the command (environment settings, ulimit).
  int run(const std::string& args, std::string& out, std::string& err,
          const std::string& prefix = "") const {
    const int status =
        exit_status(prefix + std::string(TIERLIFT_CLI_PATH) + " " + args + " > " +
                    (dir / "out.txt").string() + " 2> " + (dir / "err.txt").string());
    out = read(dir / "out.txt");
    err = read(dir / "err.txt");
    return status;
  }
  static int exit_status(const std::string& command) {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  static std::string read(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  // `tierlift glow -q --backend all` on the shipped scene listings/scenes/<scene>: images into
  // dir/out, stdout and stderr into dir/log.txt (glow_log); the exit status.
  int glow_shipped_scene(const std::string& scene) const {
    const std::filesystem::path file =
        std::filesystem::path(TIERLIFT_SOURCE_DIR) / "listings" / "scenes" / scene;
    return run_cli("glow -q --backend all --scene " + file.string() + " -o " +
                       (dir / "out").string(),
                   dir / "log.txt");
  }
  std::string glow_log() const { return read(dir / "log.txt"); }
  // `tierlift glow <flags>--scene dir/bad.json -o dir/out`, bad.json holding `json`: it must
  // exit 1 and write nothing. The log, for the caller's checks of the positioned error.
  std::string glow_refuses_scene(const std::string& json, const std::string& flags = "") const {
    const std::filesystem::path scene = dir / "bad.json", log = dir / "log.txt", out = dir / "out";
    std::ofstream(scene) << json;
    EXPECT_EQ(run_cli("glow " + flags + "--scene " + scene.string() + " -o " + out.string(), log),
              1)
        << read(log);
    EXPECT_FALSE(std::filesystem::exists(out)) << read(log);
    return read(log);
  }
  // <prefix><way>.png written in `folder` for each of the three ways.
  static void expect_each_way(const std::filesystem::path& folder, const std::string& prefix) {
    for (const char* way : {"cpu", "vulkan", "analytic"})
      EXPECT_TRUE(std::filesystem::exists(folder / (prefix + way + ".png"))) << prefix << way;
  }
  std::filesystem::path dir;
};

} // namespace tierlift::cli_test
