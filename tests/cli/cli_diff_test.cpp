// `tierlift diff`: hand-made PFM images whose differences are worked out by hand.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "cli_test_util.h"
#include "tierlift/image/io.h"

namespace tierlift::test {
namespace {

namespace fs = std::filesystem;

// A little-endian RGB PFM of one row; `rgb` holds 3 floats a pixel.
void write_pfm(const fs::path& path, const std::vector<float>& rgb) {
  std::ofstream out(path, std::ios::binary);
  out << "PF\n" << rgb.size() / 3 << " 1\n-1.0\n";
  out.write(reinterpret_cast<const char*>(rgb.data()),
            static_cast<std::streamsize>(rgb.size() * sizeof(float)));
}

struct DiffFiles {
  fs::path dir = fs::temp_directory_path() / ("tierlift_diff_" + std::to_string(::getpid()));
  fs::path a = dir / "a.pfm", b = dir / "b.pfm", tall = dir / "tall.pfm";
  DiffFiles() {
    fs::create_directories(dir);
    // Four pixels: equal; G 0.5 → 0.502 (0.002, below 1/255); B 0.25 → 0.3 (0.05);
    // R 0 → 1 (1).
    write_pfm(a, {0.1f, 0.1f, 0.1f, 0.5f, 0.5f, 0.5f, 0.25f, 0.25f, 0.25f, 0.0f, 0.0f, 0.0f});
    write_pfm(b, {0.1f, 0.1f, 0.1f, 0.5f, 0.502f, 0.5f, 0.25f, 0.25f, 0.3f, 1.0f, 0.0f, 0.0f});
    std::ofstream(tall, std::ios::binary) << "PF\n1 2\n-1.0\n" << std::string(24, '\0');
  }
  ~DiffFiles() { fs::remove_all(dir); }
};

TEST(CliDiff, FiguresAndExitCodes) {
  DiffFiles f;
  // Different images and no limit: any difference is beyond the default tolerance 0.
  CliResult r = run_cli("diff " + f.a.string() + " " + f.b.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  // Off by more than 1/255: the 0.05 and the 1 (2 of 4 pixels, 50 %).
  EXPECT_NE(r.out.find("2 of 4 pixels (50.0000 %)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("max abs 1 (R at 3,0)"), std::string::npos) << r.out;
  // The worst pixel first, with both values.
  EXPECT_NE(r.out.find("3,0: (0, 0, 0, 1) | (1, 0, 0, 1), 1 (R)"), std::string::npos) << r.out;
  EXPECT_EQ(run_cli("diff " + f.a.string() + " " + f.b.string() + " --tolerance 1").exit_code, 0);
  EXPECT_EQ(run_cli("diff " + f.a.string() + " " + f.b.string() + " --tolerance 0.9").exit_code, 1);
  EXPECT_EQ(run_cli("diff " + f.a.string() + " " + f.a.string()).exit_code, 0);
  EXPECT_EQ(run_cli("diff " + f.a.string() + " " + f.b.string() + " --max-off-share 0.5").exit_code,
            0);
  EXPECT_EQ(
      run_cli("diff " + f.a.string() + " " + f.b.string() + " --max-off-share 0.49").exit_code, 1);
  // --off-by 13: 0.05 is 12.75 steps, so only the 1 is off: 25 %.
  r = run_cli("diff " + f.a.string() + " " + f.b.string() + " --off-by 13 --max-off-share 0.25");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("1 of 4 pixels (25.0000 %)"), std::string::npos) << r.out;
}

TEST(CliDiff, Json) {
  DiffFiles f;
  CliResult r = run_cli("diff " + f.a.string() + " " + f.b.string() + " --worst 2 --json");
  EXPECT_EQ(r.exit_code, 1);
  nlohmann::json j = nlohmann::json::parse(r.out);
  const nlohmann::json& res = j["result"];
  EXPECT_DOUBLE_EQ(res["max_abs"].get<double>(), 1.0);
  EXPECT_EQ(res["off_pixels"].get<int>(), 2);
  EXPECT_DOUBLE_EQ(res["off_share"].get<double>(), 0.5);
  ASSERT_EQ(res["worst"].size(), 2u);
  EXPECT_EQ(res["worst"][0]["x"].get<int>(), 3);
  EXPECT_EQ(res["worst"][1]["x"].get<int>(), 2);
  EXPECT_EQ(res["worst"][1]["channel"].get<std::string>(), "B");
  // RMSE over the 16 values (alpha reads 1 in both): 0.002, 0.05 and 1 as stored in float.
  const double d1 = double(0.502f) - double(0.5f), d2 = double(0.3f) - double(0.25f);
  EXPECT_NEAR(res["rmse"].get<double>(), std::sqrt((d1 * d1 + d2 * d2 + 1.0) / 16.0), 1e-9);
  EXPECT_FALSE(res["within_tolerance"].get<bool>());
}

TEST(CliDiff, HeatMapIsWrittenAndNeverOverAnInput) {
  DiffFiles f;
  const fs::path heat = f.dir / "heat.png";
  CliResult r =
      run_cli("diff " + f.a.string() + " " + f.b.string() + " --heatmap " + heat.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  img::ImageResult h = img::read_png(heat.string());
  ASSERT_TRUE(h) << h.message();
  ASSERT_EQ(h->width, 4u);
  EXPECT_EQ(h->at(0, 0)[0], 0.0f);                             // equal: black
  for (int c = 0; c < 4; ++c) EXPECT_EQ(h->at(3, 0)[c], 1.0f); // the largest: white
  // Onto an input: refused before anything is read or written.
  const std::string before = read_all(f.a);
  r = run_cli("diff " + f.a.string() + " " + f.b.string() + " --heatmap " + f.a.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_all(f.a), before);
}

TEST(CliDiff, SizeMismatchAndBadInputs) {
  DiffFiles f;
  CliResult r = run_cli("diff " + f.a.string() + " " + f.tall.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("image sizes differ: 4x1 vs 1x2"), std::string::npos) << r.err;
  EXPECT_EQ(run_cli("diff " + f.a.string() + " " + (f.dir / "missing.png").string()).exit_code, 2);
  EXPECT_EQ(run_cli("diff " + f.a.string()).exit_code, 2);
  EXPECT_EQ(run_cli("diff " + f.a.string() + " " + f.b.string() + " --off-by -1").exit_code, 2);
  EXPECT_EQ(run_cli("diff " + f.a.string() + " " + f.b.string() + " --max-off-share 2").exit_code,
            2);
  // builtin: textures are images too.
  EXPECT_EQ(run_cli("diff builtin:checker:8x8 builtin:checker:8x8").exit_code, 0);
}

} // namespace
} // namespace tierlift::test
