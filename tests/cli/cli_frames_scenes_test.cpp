// The frames path of `tierlift glow` on the shipped scenes that change from frame to frame:
// the after-image writes exactly its frames and compares the devices frame by frame, the
// runaway variant warns and names the fix, the radial star moves (its frames differ), and bad
// --frames values are usage errors that write nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include "cli_fixture.h"

namespace {

namespace fs = std::filesystem;

class CliFramesScenes : public tierlift::cli_test::CliFixture {
protected:
  static std::string shipped(const char* name) {
    return (fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "scenes" / name).string();
  }
  std::set<std::string> written(const fs::path& folder) const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(folder)) names.insert(e.path().filename());
    return names;
  }
};

TEST_F(CliFramesScenes, AfterimageWritesItsFramesAndComparesThemOneByOne) {
  std::string out, err;
  const fs::path o = dir / "out";
  ASSERT_EQ(run("glow -q --backend both --frames 4 --scene " + shipped("afterimage.json") + " -o " +
                    o.string(),
                out, err),
            0)
      << err;
  const std::set<std::string> names = written(o);
  for (const char* f :
       {"frame-0001.png", "frame-0002.png", "frame-0003.png", "frame-0004.png", "frames-strip.png"})
    EXPECT_TRUE(names.contains(f)) << f;
  EXPECT_FALSE(names.contains("frame-0005.png"));
  EXPECT_EQ(std::count_if(names.begin(), names.end(),
                          [](const std::string& n) { return n.starts_with("frame-0"); }),
            4);
  EXPECT_NE(out.find("frames cpu · vulkan: 4/4 within targets"), std::string::npos) << out;
  EXPECT_NE(out.find("every pair within design.md's targets"), std::string::npos) << out;
}

TEST_F(CliFramesScenes, RunawayAfterimageWarnsAndNamesTheFix) {
  std::string out, err;
  ASSERT_EQ(run("glow -q --backend cpu --frames 2 --scene " + shipped("afterimage-runaway.json"),
                out, err),
            0)
      << err;
  EXPECT_NE(err.find("warning:"), std::string::npos) << err;
  EXPECT_NE(err.find("loop gain 1.15 >= 1, the feedback runs away"), std::string::npos) << err;
  EXPECT_NE(err.find("keep afterimage.gain below 1"), std::string::npos) << err;
}

TEST_F(CliFramesScenes, RadialStarMovesOverTheFrames) {
  std::string out, err;
  ASSERT_EQ(run("glow --backend all --frames 3 --scene " + shipped("radial-beams.json") + " -o " +
                    (dir / "out").string(),
                out, err),
            0)
      << err;
  EXPECT_NE(out.find("frames 12..14"), std::string::npos) << out; // the scene's frame is 12
  for (const char* pair : {"cpu · vulkan", "cpu · analytic", "vulkan · analytic"})
    EXPECT_NE(out.find(std::string("frames ") + pair + ": 3/3 within targets"), std::string::npos)
        << pair << "\n"
        << out;
  const std::string f1 = read(dir / "out" / "frame-0001.png");
  const std::string f3 = read(dir / "out" / "frame-0003.png");
  EXPECT_FALSE(f1.empty());
  EXPECT_NE(f1, f3); // the star moved
  // Without --frames the one frame shown is named, with how to see the others.
  ASSERT_EQ(run("glow -q --backend cpu --scene " + shipped("radial-beams.json"), out, err), 0);
  EXPECT_NE(err.find("the star moves from frame to frame"), std::string::npos) << err;
}

TEST_F(CliFramesScenes, BadFramesAreUsageErrorsThatWriteNothing) {
  for (const char* bad : {"0", "-1", "ten", "100001"}) {
    std::string out, err;
    const fs::path o = dir / "out";
    EXPECT_EQ(run(std::string("glow --backend cpu --frames ") + bad + " --scene " +
                      shipped("afterimage.json") + " -o " + o.string(),
                  out, err),
              2)
        << bad << ": " << err;
    EXPECT_NE(err.find("--frames"), std::string::npos) << bad << ": " << err;
    EXPECT_FALSE(fs::exists(o)) << bad;
  }
}

} // namespace
