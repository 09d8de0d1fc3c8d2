// The pipeline cache kept across runs: after a draw and save_pipeline_cache(), the user's
// cache directory holds the driver's cache data, which starts with the header the Vulkan
// specification fixes (VkPipelineCacheHeaderVersionOne: 32 bytes, version 1); with
// TIERLIFT_PIPELINE_CACHE=off nothing is written.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <vector>

#include "resident_fixture.h"

namespace tierlift::vulkan::test {
namespace {

namespace fs = std::filesystem;

// Draws one small pass on a device of its own (the cache belongs to the device).
void draw_once(Device& d) {
  TextureSet set(d);
  TextureId src{}, dst{};
  ASSERT_TRUE(succeeded(set.create(4, 4, img::Format::RGBA32F), src));
  ASSERT_TRUE(succeeded(set.create(4, 4, img::Format::RGBA32F), dst));
  StageTextures stages{};
  stages[0] = src;
  cpu::Pass p = quad_pass(two_coords_vs(), copy_ps(), {{0, 0, 0, 0}, {0, 0, 0, 0}}, {},
                          cpu::BlendMode::Replace);
  ir::Result<pass::DrawReport> r = set.draw(p, stages, dst);
  ASSERT_TRUE(r.ok()) << r.message();
}

class PipelineCacheFile : public ::testing::Test {
protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("tierlift_pcache_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
           "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    const char* old = std::getenv("XDG_CACHE_HOME");
    saved = old ? old : "";
    had = old != nullptr;
    setenv("XDG_CACHE_HOME", dir.c_str(), 1);
  }
  void TearDown() override {
    if (had)
      setenv("XDG_CACHE_HOME", saved.c_str(), 1);
    else
      unsetenv("XDG_CACHE_HOME");
    unsetenv("TIERLIFT_PIPELINE_CACHE");
    fs::remove_all(dir);
  }
  std::vector<fs::path> files() const {
    std::vector<fs::path> out;
    if (fs::exists(dir / "tierlift"))
      for (const auto& e : fs::directory_iterator(dir / "tierlift")) out.push_back(e.path());
    return out;
  }
  // A device of the test's own device, one draw, the cache saved: the one file it wrote.
  // `d` stays empty when create_device skipped or failed.
  std::optional<fs::path> draw_and_save(std::unique_ptr<Device>& d) {
    create_device(d);
    if (!d) return std::nullopt;
    draw_once(*d);
    d->save_pipeline_cache();
    const std::vector<fs::path> saved_files = files();
    EXPECT_EQ(saved_files.size(), 1u);
    if (saved_files.size() != 1) return std::nullopt;
    return saved_files[0];
  }
  static std::string contents(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  // A device of the test's own (the cache belongs to the device), its driver kept loaded so
  // that the driver's lifetime allocations stay attributable (lsan.supp). As for the shared
  // devices, only a machine without any Vulkan device may skip, and not under
  // TIERLIFT_REQUIRE_VULKAN; any other failure fails the test. `d` stays empty then.
  void create_device(std::unique_ptr<Device>& d) {
    ir::Result<std::unique_ptr<Device>> created = Device::create({});
    if (!created) {
      if (ir::failed_with(created, kNoDeviceRule))
        TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, created.message());
      FAIL() << created.message();
    }
    d = std::move(created).value();
    pin_loaded_modules();
  }
  fs::path dir;
  std::string saved;
  bool had = false;
};

TEST_F(PipelineCacheFile, SavedWithTheSpecsHeader) {
  std::unique_ptr<Device> d;
  const std::optional<fs::path> saved_file = draw_and_save(d);
  if (!saved_file) return; // skipped, or failed above
  EXPECT_EQ(saved_file->extension(), ".bin");
  const std::string data = contents(*saved_file);
  ASSERT_GE(data.size(), 32u);
  uint32_t header_size = 0, version = 0;
  std::memcpy(&header_size, data.data(), 4);
  std::memcpy(&version, data.data() + 4, 4);
  EXPECT_EQ(header_size, 32u);
  EXPECT_EQ(version, 1u); // VK_PIPELINE_CACHE_HEADER_VERSION_ONE
  // A second device starts from that file and draws the same (the driver accepts it).
  std::unique_ptr<Device> again;
  create_device(again);
  ASSERT_TRUE(again);
  draw_once(*again);
}

// A save whose data is what this process last wrote to the file is skipped: the file keeps
// what is there now (here a marker in its place), where the save used to write it again after
// every run.
TEST_F(PipelineCacheFile, UnchangedDataIsNotWrittenAgain) {
  std::unique_ptr<Device> d;
  const std::optional<fs::path> saved_file = draw_and_save(d);
  if (!saved_file) return; // skipped, or failed above
  const std::string first = contents(*saved_file);
  std::ofstream(*saved_file, std::ios::binary | std::ios::trunc) << "marker";
  draw_once(*d); // a new pipeline: the cache is dirty again
  d->save_pipeline_cache();
  const std::string now = contents(*saved_file);
  if (first.size() == 32) // lavapipe: the header only, the same bytes as before
    EXPECT_EQ(now, "marker");
  else // a driver whose cache grew writes the new data
    EXPECT_NE(now, "marker");
}

TEST_F(PipelineCacheFile, OffWritesNothing) {
  setenv("TIERLIFT_PIPELINE_CACHE", "off", 1);
  std::unique_ptr<Device> d;
  create_device(d);
  if (!d) return; // skipped or failed in create_device
  draw_once(*d);
  d->save_pipeline_cache();
  d.reset();
  EXPECT_TRUE(files().empty());
}

} // namespace
} // namespace tierlift::vulkan::test
