// A test fixture for running the built `tierlift` binary: a fresh temporary folder per test
// (removed afterwards) and a whole-file reader for what the CLI wrote there.
#pragma once

#include <gtest/gtest.h>

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
  static std::string read(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  std::filesystem::path dir;
};

} // namespace tierlift::cli_test
