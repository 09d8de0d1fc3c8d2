// The command line where the machine is short of something: memory (`run` plans its peak
// before allocating), address space (lavapipe cannot create its device under a tight
// `ulimit -v`), a crash it cannot prevent (the handler names the stage), or a Vulkan driver
// (`--backend all` runs what the machine has and says what it left out). Each must end in
// words, never a bare exit status or a VkResult number. And a legal HDR input (one +inf
// texel) through `glow` on every way.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>

#include "cli_fixture.h"
#include "tierlift/image/io.h"

namespace {

namespace fs = std::filesystem;

// Under AddressSanitizer the crash handler hands the signal on to ASan's own handler, which
// reports and exits 1: the exit status and the exact standard error are not checked there.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

// The loader pointed at no driver: no Vulkan device on this machine.
constexpr const char* kNoVulkan = "VK_ICD_FILENAMES=/nonexistent VK_DRIVER_FILES=/nonexistent ";

class CliDevices : public tierlift::cli_test::CliFixture {
protected:
  std::string listing() {
    const fs::path ps = dir / "red.psh";
    std::ofstream(ps) << "ps_2_0\ndef c0, 1, 0, 0, 1\nmov oC0, c0\n";
    return ps.string();
  }
  // A small opaque scene for glow.
  std::string scene() {
    const fs::path s = dir / "scene.json";
    std::ofstream(s)
        << R"({"image": "builtin:neon", "size": [24, 16], "glow": {"format": "rgba32f", "downsample": 2}})";
    return s.string();
  }
  // sh -c '<script>' with the last command's stdout and stderr apart; the raw wait status.
  // Scripts exec tierlift, so no shell waits for it to add its own "Segmentation fault".
  int raw(const std::string& script, std::string& out, std::string& err) const {
    const std::string command = "sh -c '" + script + " > " + (dir / "out.txt").string() + " 2> " +
                                (dir / "err.txt").string() + "'";
    const int status = std::system(command.c_str());
    out = read(dir / "out.txt");
    err = read(dir / "err.txt");
    return status;
  }
  static bool died_of(int status, int sig) {
    if (kSanitized) return true;
    return (WIFSIGNALED(status) && WTERMSIG(status) == sig) ||
           (WIFEXITED(status) && WEXITSTATUS(status) == 128 + sig);
  }
};

TEST_F(CliDevices, RunPlansItsMemoryBeforeAllocating) {
  std::string out, err;
  // 4096² RGBA32F is 256 MiB a copy; a 64 MiB budget refuses it before anything is made.
  EXPECT_EQ(run("run --ps " + listing() + " --size 4096x4096 --backend cpu", out, err,
                "TIERLIFT_MEMORY_LIMIT=67108864 "),
            1);
  EXPECT_NE(err.find("the 4096x4096 rgba32f target on cpu needs"), std::string::npos) << err;
  EXPECT_NE(err.find("64.0 MiB (67108864 bytes) is available"), std::string::npos) << err;
  EXPECT_EQ(run("run --json --ps " + listing() + " --size 4096x4096 --backend both", out, err,
                "TIERLIFT_MEMORY_LIMIT=67108864 "),
            1);
  const nlohmann::json j = nlohmann::json::parse(out);
  EXPECT_EQ(j["diagnostics"][0]["rule"], "memory") << out;
  EXPECT_NE(j["diagnostics"][0]["message"].get<std::string>().find("cpu + vulkan"),
            std::string::npos)
      << out;
  // Within the budget the same run goes ahead.
  EXPECT_EQ(run("run --ps " + listing() + " --size 64x64 --backend cpu", out, err,
                "TIERLIFT_MEMORY_LIMIT=268435456 "),
            0)
      << err;
}

TEST_F(CliDevices, GlowWithoutVulkanRunsWhatTheMachineHas) {
  std::string out, err;
  EXPECT_EQ(run("glow -q --backend cpu,analytic --scene " + scene(), out, err, kNoVulkan), 0)
      << err;
  EXPECT_NE(out.find("cpu · analytic"), std::string::npos) << out;
  EXPECT_EQ(err.find("Vulkan"), std::string::npos) << err; // nothing left out: no note
  // The default, all: the two ways it has, and a note saying what it left out.
  EXPECT_EQ(run("glow -q --scene " + scene(), out, err, kNoVulkan), 0) << err;
  EXPECT_NE(err.find("warning: no Vulkan device: ran cpu and analytic only"), std::string::npos)
      << err;
  EXPECT_EQ(out.find("vulkan"), std::string::npos) << out;
  EXPECT_EQ(run("glow --json --scene " + scene(), out, err, kNoVulkan), 0) << err;
  const nlohmann::json j = nlohmann::json::parse(out);
  EXPECT_EQ(j["result"]["backends"]["ran"], nlohmann::json::array({"cpu", "analytic"})) << out;
  EXPECT_NE(j["result"]["backends"]["note"].get<std::string>().find("no Vulkan device"),
            std::string::npos);
  ASSERT_EQ(j["result"]["agreement"].size(), 1u) << out;
  EXPECT_EQ(j["result"]["agreement"][0]["pair"], nlohmann::json::array({"cpu", "analytic"}));
  // Vulkan asked for by name: an error in words.
  EXPECT_EQ(run("glow -q --backend vulkan --scene " + scene(), out, err, kNoVulkan), 2);
  EXPECT_NE(err.find("--backend names vulkan: no Vulkan device found"), std::string::npos) << err;
  EXPECT_EQ(run("glow -q --backend cpu,gpu --scene " + scene(), out, err), 2);
  EXPECT_NE(err.find("'gpu' is not a way"), std::string::npos) << err;
}

TEST_F(CliDevices, RunTakesBackendListsAndFallsBackWithoutVulkan) {
  std::string out, err;
  EXPECT_EQ(run("run --ps " + listing() + " --size 4x4 --probe 0,0 --backend vulkan,cpu", out, err),
            0)
      << err;
  EXPECT_NE(out.find("cpu vs vulkan"), std::string::npos) << out;
  EXPECT_EQ(run("run --ps " + listing() + " --size 4x4 --backend all", out, err, kNoVulkan), 0)
      << err;
  EXPECT_NE(err.find("no Vulkan device: ran cpu only"), std::string::npos) << err;
  EXPECT_EQ(run("run --ps " + listing() + " --size 4x4 --backend both", out, err, kNoVulkan), 2);
  EXPECT_NE(err.find("--backend names vulkan"), std::string::npos) << err;
}

TEST_F(CliDevices, CrashHandlerNamesTheStageAndKeepsTheExitStatus) {
  std::string out, err;
  const std::string tierlift = TIERLIFT_CLI_PATH;
  int status = raw("exec env TIERLIFT_TEST_CRASH=vulkan-device " + tierlift + " run --json --ps " +
                       listing() + " --size 4x4 --backend vulkan",
                   out, err);
  EXPECT_TRUE(died_of(status, SIGSEGV)) << status;
  // --json: the document is all the output.
  if (!kSanitized) {
    EXPECT_TRUE(err.empty()) << err;
  }
  const nlohmann::json j = nlohmann::json::parse(out); // one document, nothing else
  EXPECT_EQ(j["command"], "run");
  EXPECT_EQ(j["exit_code"], 128 + SIGSEGV);
  EXPECT_EQ(j["ok"], false);
  ASSERT_EQ(j["diagnostics"].size(), 1u);
  EXPECT_EQ(j["diagnostics"][0]["rule"], "crash");
  EXPECT_EQ(j["diagnostics"][0]["message"],
            "crashed (SIGSEGV, segmentation fault) in the Vulkan driver while creating the "
            "device");
  // A pass on the interpreter, without --json: the line only, naming the pass.
  status = raw("exec env TIERLIFT_TEST_CRASH=pass " + tierlift + " run --ps " + listing() +
                   " --size 4x4 --backend cpu",
               out, err);
  EXPECT_TRUE(died_of(status, SIGSEGV)) << status;
  const std::string line = "tierlift run: error: crashed (SIGSEGV, segmentation fault) while "
                           "running pass 'run' on cpu\n";
  if (kSanitized) {
    EXPECT_EQ(err.find(line), 0u) << err;
  } else {
    EXPECT_EQ(err, line);
  }
  EXPECT_TRUE(out.empty()) << out;
}

TEST_F(CliDevices, AddressSpaceLimitIsASentenceNotACrash) {
  std::string out, err;
  const std::string tierlift = TIERLIFT_CLI_PATH;
  // lavapipe's vkCreateDevice segfaults under this limit in most runs; tierlift refuses first.
  // AddressSanitizer reserves terabytes of shadow address space at start, so a sanitized
  // tierlift cannot start at all under `ulimit -v`: there is nothing of ours to check there.
  if (kSanitized) GTEST_SKIP() << "a sanitized binary cannot start under ulimit -v";
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int status = raw("ulimit -v 400000; exec " + tierlift + " run --ps " + listing() +
                               " --size 4x4 --backend vulkan",
                           out, err);
    EXPECT_FALSE(died_of(status, SIGSEGV)) << err;
    ASSERT_TRUE(WIFEXITED(status)) << status;
    EXPECT_EQ(WEXITSTATUS(status), 2) << err;
    EXPECT_NE(err.find("the address-space limit (ulimit -v 400000)"), std::string::npos) << err;
  }
}

TEST_F(CliDevices, GlowOfAnInfiniteTexelAgreesOnEveryWay) {
  // The report's input: a PFM scene with one +inf texel (PFM has no alpha: every texel is a
  // glow source). NUMERICS.md rule 36: the composite's bilinear read of the glow is NaN around
  // the texel on every way; `glow` must not call that a disagreement.
  tierlift::img::Image im(24, 16);
  for (size_t i = 3; i < im.rgba.size(); i += 4) im.rgba[i] = 1;
  float* p = im.at(11, 7);
  p[0] = p[1] = p[2] = std::numeric_limits<float>::infinity();
  const std::vector<uint8_t> bytes = tierlift::img::encode_pfm(im);
  const fs::path pfm = dir / "inf.pfm";
  std::ofstream(pfm, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  std::string out, err;
  EXPECT_EQ(run("glow -q --backend all --image " + pfm.string(), out, err), 0) << out << err;
  EXPECT_NE(out.find("every pair within design.md's targets"), std::string::npos) << out;
}

} // namespace
