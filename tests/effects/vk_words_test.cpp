// Vulkan failures in words (runtime/devices/vulkan/src/vk_internal.h): a VkResult never
// reaches the user as a number, and a failed allocation says what it was for and how big.
// (A real failure needs a 4 GiB allocation under an address-space limit, which the memory
// plans of `run` and `glow` refuse first; the words are checked here directly.)
#include <gtest/gtest.h>

#include <string>

#include "../../runtime/devices/vulkan/src/vk_internal.h"

namespace tierlift::vulkan {
namespace {

TEST(VkWords, ResultsAreWordsNotNumbers) {
  for (const VkResult r :
       {VK_ERROR_OUT_OF_HOST_MEMORY, VK_ERROR_OUT_OF_DEVICE_MEMORY, VK_ERROR_DEVICE_LOST,
        VK_ERROR_INITIALIZATION_FAILED, VK_ERROR_FORMAT_NOT_SUPPORTED, VK_ERROR_UNKNOWN}) {
    const std::string words = vk_error("vkAllocateMemory", r);
    EXPECT_EQ(words.find_first_of("0123456789"), std::string::npos) << words;
    EXPECT_EQ(words.find("VkResult"), std::string::npos) << words;
  }
  EXPECT_EQ(vk_error("vkCreateDevice", VK_ERROR_OUT_OF_HOST_MEMORY),
            "out of host memory in vkCreateDevice");
}

TEST(VkWords, AFailedAllocationSaysWhatAndHowMuch) {
  // 16384 × 16384 texels × 16 bytes = 2^32 bytes = 4.0 GiB.
  const VkFormat f = VK_FORMAT_R32G32B32A32_SFLOAT;
  EXPECT_EQ(allocation_failed(VK_ERROR_OUT_OF_DEVICE_MEMORY, image_words(16384, 16384, f),
                              image_bytes(16384, 16384, f)),
            "out of device memory while allocating a 16384x16384 RGBA32F image (4.0 GiB)");
  EXPECT_EQ(allocation_failed(VK_ERROR_OUT_OF_HOST_MEMORY, "a host buffer", 3 << 20),
            "out of host memory while allocating a host buffer (3.0 MiB)");
}

} // namespace
} // namespace tierlift::vulkan
