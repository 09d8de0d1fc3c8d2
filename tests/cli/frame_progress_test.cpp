// Progress of `--frames` runs (issue 32, item 15): run_frames tells how many frames are done,
// and `tierlift glow --frames` shows it as one line on a terminal only.
#include <gtest/gtest.h>

#include <fstream>
#include <utility>
#include <vector>

#include "cli_fixture.h"
#include "tierlift/effects/graph/device.h"
#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/effects/graph/single_pass.h"
#include "tierlift/pass/setup.h"

namespace tierlift::effects {
namespace {

TEST(FrameProgress, RunFramesCountsEachFrame) {
  pass::RunRequest r;
  r.width = r.height = 2;
  r.inputs.push_back({ir::RegFile::Input, 0, {1, 0.5f, 0.25f, 1}});
  ir::Result<pass::Pass> p = pass::prepare_pass(r);
  ASSERT_TRUE(p) << p.message();
  ir::Result<EffectGraph> g = single_pass_graph(*p, 2, 2, img::Format::RGBA32F);
  ASSERT_TRUE(g) << g.message();
  CpuPassDevice device(1);
  ImageMap images;
  std::vector<std::pair<unsigned, unsigned>> calls;
  ir::Result<FrameTimes> t =
      run_frames(*g, device, images, 3, {}, {}, [&](unsigned done, unsigned n) {
        calls.push_back({done, n});
      });
  ASSERT_TRUE(t) << t.message();
  EXPECT_EQ(calls, (std::vector<std::pair<unsigned, unsigned>>{{1, 3}, {2, 3}, {3, 3}}));
}

class CliFrameProgress : public cli_test::CliFixture {};

TEST_F(CliFrameProgress, OnATerminalOnly) {
  const std::filesystem::path scene = dir / "small.json";
  std::ofstream(scene) << "{\"size\": [32, 16]}\n";
  const std::string args =
      "glow --scene " + scene.string() + " --backend cpu --frames 3 --downsample 2";
  std::string out, err;
  // A pipe or a file: no progress line.
  ASSERT_EQ(run(args, out, err), 0) << err;
  EXPECT_EQ(err.find("frame 1/3"), std::string::npos) << err;
  // A terminal (script gives the command one): the line, updated in place.
  const std::filesystem::path typescript = dir / "tty.txt";
  const int status = exit_status("script -qec \"" + std::string(TIERLIFT_CLI_PATH) + " " + args +
                                 "\" " + typescript.string() + " > /dev/null 2>&1");
  ASSERT_EQ(status, 0);
  const std::string tty = read(typescript);
  EXPECT_NE(tty.find("[glow] cpu: frame 1/3"), std::string::npos) << tty;
  EXPECT_NE(tty.find("\r\033[K"), std::string::npos);
  // -q: none, even on a terminal.
  ASSERT_EQ(exit_status("script -qec \"" + std::string(TIERLIFT_CLI_PATH) + " " + args + " -q\" " +
                        typescript.string() + " > /dev/null 2>&1"),
            0);
  EXPECT_EQ(read(typescript).find("frame 1/3"), std::string::npos);
}

} // namespace
} // namespace tierlift::effects
