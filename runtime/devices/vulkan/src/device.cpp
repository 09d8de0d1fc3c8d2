// Instance, physical device choice, queue and command pool; the validation messenger.
#include <algorithm>
#include <cctype>
#include <cstring>

#include <fmt/format.h>

#include "address_space.h"
#include "pipeline_cache.h"
#include "tierlift/crash/crash.h"
#include "unorm8_probe.h"
#include "unorm8_to_float.h"
#include "vk_internal.h"

namespace tierlift::vulkan {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kNoDriverHint =
    "no Vulkan device found: install a Vulkan driver, e.g. the Debian package "
    "mesa-vulkan-drivers (lavapipe, a CPU implementation)";

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data,
                                          void* user) {
  auto* impl = static_cast<Device::Impl*>(user);
  const char* sev = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
  std::string line =
      fmt::format("{}: [{}] {}", sev, data && data->pMessageIdName ? data->pMessageIdName : "",
                  data && data->pMessage ? data->pMessage : "");
  std::lock_guard<std::mutex> lock(impl->messages_mutex);
  impl->messages.push_back(std::move(line));
  return VK_FALSE; // never abort the call
}

VkDebugUtilsMessengerCreateInfoEXT messenger_info(Device::Impl* impl) {
  VkDebugUtilsMessengerCreateInfoEXT ci{};
  ci.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  ci.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  ci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                   VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                   VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  ci.pfnUserCallback = on_message;
  ci.pUserData = impl;
  return ci;
}

bool has_layer(const char* name) {
  uint32_t n = 0;
  if (vkEnumerateInstanceLayerProperties(&n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(n);
  if (vkEnumerateInstanceLayerProperties(&n, layers.data()) != VK_SUCCESS) return false;
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
    return std::strcmp(l.layerName, name) == 0;
  });
}

// Whether the physical device offers VK_EXT_non_seamless_cube_map and its nonSeamlessCubeMap
// feature: samplers that filter each cube face on its own, as Direct3D 9 does.
bool offers_non_seamless_cubes(VkPhysicalDevice pd) {
  uint32_t n = 0;
  if (vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> extensions(n);
  if (vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, extensions.data()) != VK_SUCCESS)
    return false;
  extensions.resize(n);
  const bool listed =
      std::any_of(extensions.begin(), extensions.end(), [](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, VK_EXT_NON_SEAMLESS_CUBE_MAP_EXTENSION_NAME) == 0;
      });
  if (!listed) return false;
  VkPhysicalDeviceNonSeamlessCubeMapFeaturesEXT feature{};
  feature.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_NON_SEAMLESS_CUBE_MAP_FEATURES_EXT;
  VkPhysicalDeviceFeatures2 features{};
  features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  features.pNext = &feature;
  vkGetPhysicalDeviceFeatures2(pd, &features); // core in Vulkan 1.1, which tierlift requires
  return feature.nonSeamlessCubeMap == VK_TRUE;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

} // namespace

std::string vk_result_words(VkResult r) {
  switch (r) {
  case VK_ERROR_OUT_OF_HOST_MEMORY: return "out of host memory";
  case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "out of device memory";
  case VK_ERROR_INITIALIZATION_FAILED: return "the driver could not initialise";
  case VK_ERROR_DEVICE_LOST: return "the device was lost (the driver failed)";
  case VK_ERROR_MEMORY_MAP_FAILED: return "the memory could not be mapped";
  case VK_ERROR_LAYER_NOT_PRESENT: return "a Vulkan layer is missing";
  case VK_ERROR_EXTENSION_NOT_PRESENT: return "a Vulkan extension is missing";
  case VK_ERROR_FEATURE_NOT_PRESENT: return "a device feature is missing";
  case VK_ERROR_INCOMPATIBLE_DRIVER: return "no compatible Vulkan driver";
  case VK_ERROR_TOO_MANY_OBJECTS: return "too many Vulkan objects";
  case VK_ERROR_FORMAT_NOT_SUPPORTED: return "the format is not supported";
  case VK_ERROR_FRAGMENTED_POOL:
  case VK_ERROR_OUT_OF_POOL_MEMORY: return "out of descriptor pool memory";
  case VK_TIMEOUT: return "the device timed out";
  default: return "an error the driver did not name";
  }
}

std::string vk_error(const char* what, VkResult r) {
  return fmt::format("{} in {}", vk_result_words(r), what);
}

Device::Impl::~Impl() {
  if (device) {
    vkDeviceWaitIdle(device);
    unorm8.reset();
    vulkan::save_pipeline_cache(*this);
    if (pipeline_cache) vkDestroyPipelineCache(device, pipeline_cache, nullptr);
    if (pool) vkDestroyCommandPool(device, pool, nullptr);
    vkDestroyDevice(device, nullptr);
  }
  if (messenger) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance, messenger, nullptr);
  }
  if (instance) vkDestroyInstance(instance, nullptr);
  // The messenger given to vkCreateInstance stays active through vkDestroyInstance, so the
  // layer's leak reports of both destroy calls are in `messages` by now.
  if (on_destroyed) {
    std::lock_guard<std::mutex> lock(messages_mutex);
    on_destroyed(messages);
  }
}

Device::Device(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Device::~Device() = default;

namespace {

// Every failure is kDeviceRule unless it is one of the two "no device" cases (kNoDeviceRule).
ir::Failure device_failure(std::string msg, std::string_view rule = kDeviceRule) {
  return ir::fail("vulkan", std::string(rule), std::move(msg));
}

// The instance, with the validation layer and its messenger when asked for.
ir::Status create_instance(Device::Impl& impl, const DeviceOptions& options) {
  std::vector<const char*> layers, extensions;
  if (options.validation) {
    if (!has_layer(kValidationLayer))
      return device_failure(
          "the Vulkan validation layer VK_LAYER_KHRONOS_validation is not installed: "
          "install the Debian package vulkan-validationlayers");
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (options.synchronization_validation)
      extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME); // provided by the layer
  }
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "tierlift";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo ici{};
  ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  ici.pApplicationInfo = &app;
  ici.enabledLayerCount = static_cast<uint32_t>(layers.size());
  ici.ppEnabledLayerNames = layers.data();
  ici.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  ici.ppEnabledExtensionNames = extensions.data();
  VkDebugUtilsMessengerCreateInfoEXT mci = messenger_info(&impl);
  if (options.validation) ici.pNext = &mci; // messages of vkCreate/DestroyInstance too
  const VkValidationFeatureEnableEXT sync =
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{};
  features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = &sync;
  if (options.validation && options.synchronization_validation) {
    features.pNext = &mci;
    ici.pNext = &features;
  }
  const VkResult r = vkCreateInstance(&ici, nullptr, &impl.instance);
  if (r != VK_SUCCESS) {
    impl.instance = VK_NULL_HANDLE;
    // The loader answers INCOMPATIBLE_DRIVER when it finds no driver (ICD) at all. Anything
    // else (out of memory, a layer or extension missing, initialization failed) is a fault
    // of an installed Vulkan, not its absence.
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER) return device_failure(kNoDriverHint, kNoDeviceRule);
    return device_failure(vk_error("vkCreateInstance", r));
  }
  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(impl.instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create || create(impl.instance, &mci, nullptr, &impl.messenger) != VK_SUCCESS)
      return device_failure(
          "cannot create the VK_EXT_debug_utils messenger of the validation layer");
  }
  return ir::ok_status();
}

// The physical device: the first CPU device (lavapipe), or the first whose name contains
// options.gpu_filter; its properties, and whether its point sampler floors as lavapipe's.
ir::Status choose_physical_device(Device::Impl& impl, const DeviceOptions& options) {
  uint32_t count = 0;
  VkResult r = vkEnumeratePhysicalDevices(impl.instance, &count, nullptr);
  if (r != VK_SUCCESS) return device_failure(vk_error("vkEnumeratePhysicalDevices", r));
  std::vector<VkPhysicalDevice> devices(count);
  if (count) r = vkEnumeratePhysicalDevices(impl.instance, &count, devices.data());
  if (r != VK_SUCCESS && r != VK_INCOMPLETE)
    return device_failure(vk_error("vkEnumeratePhysicalDevices", r));
  devices.resize(count);
  if (devices.empty()) return device_failure(kNoDriverHint, kNoDeviceRule);
  VkPhysicalDevice chosen = VK_NULL_HANDLE;
  std::string names;
  for (VkPhysicalDevice pd : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(pd, &p);
    names += std::string(names.empty() ? "" : ", ") + p.deviceName;
    bool match = options.gpu_filter.empty()
                     ? p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU
                     : lower(p.deviceName).find(lower(options.gpu_filter)) != std::string::npos;
    if (match && !chosen) chosen = pd;
  }
  if (!chosen && options.gpu_filter.empty()) chosen = devices.front();
  if (!chosen)
    return device_failure(
        fmt::format("no Vulkan device matches \"{}\" (found: {})", options.gpu_filter, names));
  impl.physical = chosen;
  vkGetPhysicalDeviceProperties(chosen, &impl.props);
  vkGetPhysicalDeviceMemoryProperties(chosen, &impl.memory);
  // lavapipe (Mesa's vendor id, a CPU device named llvmpipe): its point sampler takes the
  // texel index as floor(fl32(u·N)), the interpreter's (lp_bld_sample*.c: one multiply by
  // the float size, then a floor). A GPU's fixed-point sub-texel coordinates do not.
  constexpr uint32_t kMesaVendorId = 0x10005; // VK_VENDOR_ID_MESA
  impl.point_sampling_floors = options.llvmpipe_point_sampling &&
                               impl.props.vendorID == kMesaVendorId &&
                               impl.props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU &&
                               std::string_view(impl.props.deviceName).starts_with("llvmpipe");
  if (impl.props.apiVersion < VK_API_VERSION_1_1)
    return device_failure(fmt::format(
        "{} supports only Vulkan {}.{}; tierlift needs 1.1", impl.props.deviceName,
        VK_API_VERSION_MAJOR(impl.props.apiVersion), VK_API_VERSION_MINOR(impl.props.apiVersion)));
  return ir::ok_status();
}

// The logical device with one graphics queue, and its command pool.
ir::Status create_logical_device(Device::Impl& impl, const DeviceOptions& options) {
  uint32_t qcount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(impl.physical, &qcount, nullptr);
  std::vector<VkQueueFamilyProperties> families(qcount);
  vkGetPhysicalDeviceQueueFamilyProperties(impl.physical, &qcount, families.data());
  families.resize(qcount);
  bool found = false;
  for (uint32_t i = 0; i < families.size() && !found; ++i)
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
      impl.queue_family = i;
      found = true;
    }
  if (!found) return device_failure(fmt::format("{} has no graphics queue", impl.props.deviceName));

  float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{};
  qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  qci.queueFamilyIndex = impl.queue_family;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci{};
  dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  // lavapipe crashes inside vkCreateDevice when the address-space limit leaves it too little
  // room (address_space.h): foreseen, it is a sentence instead of a SIGSEGV.
  if (impl.props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU)
    if (std::string why = address_space_refusal(cpu_device_address_space()); !why.empty())
      return device_failure(why);
  // The one optional feature: storage-buffer writes from a pixel shader, for tracing a pixel.
  VkPhysicalDeviceFeatures supported{}, wanted{};
  vkGetPhysicalDeviceFeatures(impl.physical, &supported);
  wanted.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
  impl.fragment_stores = supported.fragmentStoresAndAtomics == VK_TRUE;
  dci.pEnabledFeatures = &wanted;
  // Direct3D 9 filters each cube face on its own (NUMERICS.md T4); Vulkan filters across face
  // edges unless this extension is enabled and the sampler asks (pipeline.cpp).
  const char* non_seamless = VK_EXT_NON_SEAMLESS_CUBE_MAP_EXTENSION_NAME;
  VkPhysicalDeviceNonSeamlessCubeMapFeaturesEXT cube_feature{};
  cube_feature.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_NON_SEAMLESS_CUBE_MAP_FEATURES_EXT;
  cube_feature.nonSeamlessCubeMap = VK_TRUE;
  impl.cube_faces_alone = options.per_face_cubes && offers_non_seamless_cubes(impl.physical);
  if (impl.cube_faces_alone) {
    dci.enabledExtensionCount = 1;
    dci.ppEnabledExtensionNames = &non_seamless;
    dci.pNext = &cube_feature;
  }
  VkResult r = vkCreateDevice(impl.physical, &dci, nullptr, &impl.device);
  if (r != VK_SUCCESS) {
    impl.device = VK_NULL_HANDLE;
    return device_failure(vk_error("vkCreateDevice", r));
  }
  vkGetDeviceQueue(impl.device, impl.queue_family, 0, &impl.queue);
  VkCommandPoolCreateInfo pci{};
  pci.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pci.queueFamilyIndex = impl.queue_family;
  r = vkCreateCommandPool(impl.device, &pci, nullptr, &impl.pool);
  if (r != VK_SUCCESS) {
    impl.pool = VK_NULL_HANDLE;
    return device_failure(vk_error("vkCreateCommandPool", r));
  }
  return ir::ok_status();
}

} // namespace

ir::Result<std::unique_ptr<Device>> Device::create(const DeviceOptions& options) {
  using Created = ir::Result<std::unique_ptr<Device>>;
  // A driver that crashes here (lavapipe under a tight `ulimit -v`) gets its line.
  const crash::Stage stage("vulkan-device", "in the Vulkan driver while creating the device");
  auto impl = std::make_unique<Impl>();
  if (ir::Status s = create_instance(*impl, options); !s) return s.failure();
  if (ir::Status s = choose_physical_device(*impl, options); !s) return s.failure();
  if (ir::Status s = create_logical_device(*impl, options); !s) return s.failure();
  impl->on_destroyed = options.on_destroyed; // a device that was never made has nothing to report
  std::unique_ptr<Device> device(new Device(std::move(impl)));
  // Read every RGBA8 level once, undecoded, and keep the cheapest decode that is exact for
  // all of them (codegen/unorm8_decode.h); none exact: RGBA8 reads go through the float copy.
  Impl& d = *device->impl_;
  d.unorm8_in_place = options.unorm8_in_place;
  if (!options.choose_unorm8_decode || !options.unorm8_in_place) return Created(std::move(device));
  d.unorm8_decode = codegen::Unorm8Decode::None;
  ir::Result<std::vector<float>> levels = read_unorm8_levels(*device);
  if (!levels) return levels.failure();
  const std::optional<codegen::Unorm8Decode> decode = codegen::choose_unorm8_decode(*levels);
  d.unorm8_decode = decode.value_or(codegen::Unorm8Decode::RoundAndRebuild);
  d.unorm8_in_place = decode.has_value();
  return Created(std::move(device));
}

std::string Device::name() const {
  return impl_->props.deviceName;
}
uint32_t Device::subtexel_bits() const {
  return impl_->props.limits.subTexelPrecisionBits;
}
std::string Device::unorm8_reads() const {
  return impl_->unorm8_in_place ? codegen::unorm8_decode_name(impl_->unorm8_decode) : "float copy";
}

bool Device::cube_faces_filtered_alone() const {
  return impl_->cube_faces_alone;
}

std::vector<std::string> Device::messages() const {
  std::lock_guard<std::mutex> lock(impl_->messages_mutex);
  return impl_->messages;
}
void Device::clear_messages() {
  std::lock_guard<std::mutex> lock(impl_->messages_mutex);
  impl_->messages.clear();
}

} // namespace tierlift::vulkan
