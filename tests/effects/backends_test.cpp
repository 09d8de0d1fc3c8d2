// --backend words and lists (effects/backends.h): what each text asks for, in run order.
#include <gtest/gtest.h>

#include "tierlift/effects/graph/backends.h"

namespace tierlift::effects {
namespace {

const std::vector<std::string> kGlow = {"cpu", "vulkan", "analytic"};
const std::vector<std::string> kRun = {"cpu", "vulkan"};

std::vector<std::string> ways(std::string_view text, const std::vector<std::string>& offered) {
  ir::Result<BackendChoice> c = parse_backends(text, offered);
  EXPECT_TRUE(c.ok()) << text << ": " << c.message();
  return c ? c->ways : std::vector<std::string>{};
}

TEST(Backends, WordsKeepTheirMeaning) {
  using V = std::vector<std::string>;
  EXPECT_EQ(ways("cpu", kGlow), V{"cpu"});
  EXPECT_EQ(ways("vulkan", kGlow), V{"vulkan"});
  EXPECT_EQ(ways("analytic", kGlow), V{"analytic"});
  EXPECT_EQ(ways("both", kGlow), (V{"cpu", "vulkan"}));
  EXPECT_EQ(ways("all", kGlow), kGlow);
  EXPECT_EQ(ways("all", kRun), kRun);
  EXPECT_TRUE(parse_backends("all", kGlow)->automatic);
  EXPECT_FALSE(parse_backends("cpu,vulkan,analytic", kGlow)->automatic);
}

TEST(Backends, ListsRunInTheFixedOrder) {
  using V = std::vector<std::string>;
  EXPECT_EQ(ways("cpu,analytic", kGlow), (V{"cpu", "analytic"}));
  EXPECT_EQ(ways("analytic,cpu", kGlow), (V{"cpu", "analytic"}));
  EXPECT_EQ(ways("vulkan,cpu", kRun), (V{"cpu", "vulkan"}));
  EXPECT_EQ(ways("both,analytic", kGlow), kGlow);
}

TEST(Backends, BadListsAreRefusedInWords) {
  for (const char* bad : {"", "gpu", "cpu,", ",cpu", "cpu,,vulkan", "cpu,cpu", "both,vulkan"}) {
    ir::Result<BackendChoice> c = parse_backends(bad, kGlow);
    ASSERT_FALSE(c.ok()) << bad;
    EXPECT_NE(c.message().find("--backend"), std::string::npos) << c.message();
  }
  // run has no analytic model.
  ir::Result<BackendChoice> c = parse_backends("cpu,analytic", kRun);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.message().find("'analytic' is not a way"), std::string::npos) << c.message();
}

} // namespace
} // namespace tierlift::effects
