// The environment a `tierlift test` worker starts with (corpus::worker_environment).
#include <gtest/gtest.h>

#include <algorithm>

#include "tierlift/corpus/runner.h"

namespace tierlift::corpus {
namespace {

bool has(const std::vector<std::string>& env, const std::string& entry) {
  return std::find(env.begin(), env.end(), entry) != env.end();
}

// Unset, lavapipe's rasteriser threads are turned off; the parent's variables all pass on.
TEST(WorkerEnvironment, TurnsRasteriserThreadsOffWhenUnset) {
  char home[] = "HOME=/tmp", path[] = "PATH=/bin";
  char* parent[] = {home, path, nullptr};
  const std::vector<std::string> env = worker_environment(parent);
  EXPECT_EQ(env.size(), 3u);
  EXPECT_TRUE(has(env, "HOME=/tmp"));
  EXPECT_TRUE(has(env, "PATH=/bin"));
  EXPECT_TRUE(has(env, "LP_NUM_THREADS=0"));
}

// A number the user chose is kept, and not joined by a second one.
TEST(WorkerEnvironment, KeepsTheUsersChoice) {
  char threads[] = "LP_NUM_THREADS=3";
  char* parent[] = {threads, nullptr};
  const std::vector<std::string> env = worker_environment(parent);
  EXPECT_EQ(env, std::vector<std::string>{"LP_NUM_THREADS=3"});
}

} // namespace
} // namespace tierlift::corpus
