#include "vk/context.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "vk/keep_libraries_loaded.h"
#include "vk/pipeline_cache.h"
#include "vk/vk_check.h"

namespace prism::vk {
namespace {

constexpr const char *kValidationLayer = "VK_LAYER_KHRONOS_validation";

const char *kInstallHint =
    "Install a Vulkan driver: on Debian 12 `sudo apt install mesa-vulkan-drivers libvulkan1` "
    "gives lavapipe (runs on the CPU); a GPU needs its vendor's Vulkan driver.";

bool hasLayer(const char *name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const auto &layer : layers)
        if (std::strcmp(layer.layerName, name) == 0)
            return true;
    return false;
}

bool hasDeviceExtension(VkPhysicalDevice device, const char *name) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
    for (const auto &extension : extensions)
        if (std::strcmp(extension.extensionName, name) == 0)
            return true;
    return false;
}

int deviceTypeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return 3;
    default:
        return 4;
    }
}

} // namespace

Context::Context(const ContextOptions &options) {
    try {
        createInstance(options);
        pickPhysicalDevice(options);
        createDevice(options);
        pipelineCache_ = std::make_unique<PipelineCache>(*this, options.pipelineStore);
    } catch (...) {
        destroy(); // tolerates half-built state
        throw;
    }
}

Context::~Context() {
    destroy();
}

VkPipelineCache Context::pipelineCache() const {
    return pipelineCache_->handle();
}

uint64_t Context::savePipelineCache() const {
    return pipelineCache_->save();
}

uint64_t Context::pipelineCacheLoadedBytes() const {
    return pipelineCache_->loadedBytes();
}

const DiskCache *Context::store() const {
    return pipelineCache_->store();
}

void Context::destroy() {
    pipelineCache_.reset();
    if (device_)
        vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy)
            destroy(instance_, messenger_, nullptr);
    }
    messenger_ = VK_NULL_HANDLE;
    if (instance_)
        vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::onValidationMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT *data, void *user) {
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT)
        return VK_FALSE;
    auto *self = static_cast<Context *>(user);
    self->validationMessages_.fetch_add(1);
    std::fprintf(stderr, "prism: Vulkan validation: %s\n", data->pMessage);
    return VK_FALSE;
}

void Context::createInstance(const ContextOptions &options) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "Prism";
    app.pEngineName = "Prism";
    app.apiVersion = VK_API_VERSION_1_3;

    std::vector<const char *> extensions = options.instanceExtensions;
    std::vector<const char *> layers;
    if (options.validation) {
        if (!hasLayer(kValidationLayer))
            throw Error("Vulkan validation was requested but VK_LAYER_KHRONOS_validation is not "
                        "installed; on Debian 12: `sudo apt install vulkan-validationlayers`");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }

    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &Context::onValidationMessage;
    messengerInfo.pUserData = this;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    if (options.validation)
        info.pNext = &messengerInfo; // also reports problems in vkCreate/DestroyInstance

    VkResult result = vkCreateInstance(&info, nullptr, &instance_);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw Error(std::string("No usable Vulkan driver found. ") + kInstallHint);
    VK_CHECK(result);
    keepVulkanLibrariesLoaded(); // sanitizer builds: the driver stays for LeakSanitizer

    if (options.validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (!create)
            throw Error("VK_EXT_debug_utils is not available; cannot report validation messages");
        VK_CHECK(create(instance_, &messengerInfo, nullptr, &messenger_));
    }
}

void Context::pickPhysicalDevice(const ContextOptions &options) {
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, devices.data()));
    if (devices.empty())
        throw Error(std::string("No Vulkan device found. ") + kInstallHint);

    int bestRank = 1 << 30;
    std::string seen;
    for (VkPhysicalDevice candidate : devices) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(candidate, &props);
        seen += std::string(seen.empty() ? "" : ", ") + props.deviceName;
        if (props.apiVersion < VK_API_VERSION_1_2)
            continue;
        if (!options.deviceNameFilter.empty() &&
            std::string(props.deviceName).find(options.deviceNameFilter) == std::string::npos)
            continue;
        int rank = deviceTypeRank(props.deviceType);
        if (rank < bestRank) {
            bestRank = rank;
            physicalDevice_ = candidate;
        }
    }
    if (!physicalDevice_)
        throw Error("No suitable Vulkan 1.2+ device" +
                    (options.deviceNameFilter.empty()
                         ? std::string()
                         : " matching \"" + options.deviceNameFilter + "\"") +
                    " among: " + seen);

    vkGetPhysicalDeviceProperties(physicalDevice_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memoryProperties_);
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &driver;
    vkGetPhysicalDeviceProperties2(physicalDevice_, &props2);
    driverId_ = driver.driverID;
}

void Context::createDevice(const ContextOptions &options) {
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, families.data());
    // One queue does everything: compute for tracing, graphics for the blit in the viewer.
    bool found = false;
    for (uint32_t i = 0; i < familyCount && !found; ++i) {
        VkQueueFlags needed = VK_QUEUE_COMPUTE_BIT | VK_QUEUE_GRAPHICS_BIT;
        if ((families[i].queueFlags & needed) == needed) {
            queueFamily_ = i;
            found = true;
        }
    }
    if (!found)
        throw Error(deviceName() + " has no queue family with both graphics and compute");

    VkPhysicalDeviceShaderClockFeaturesKHR supportedClock{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_CLOCK_FEATURES_KHR};
    VkPhysicalDeviceVulkan12Features supported12{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    supported12.pNext = &supportedClock;
    VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    supported.pNext = &supported12;
    vkGetPhysicalDeviceFeatures2(physicalDevice_, &supported);
    if (!supported12.shaderBufferInt64Atomics || !supported.features.shaderInt64)
        throw Error(deviceName() + " lacks 64-bit integer buffer atomics, which the tracer's "
                                   "ray counters need");

    VkPhysicalDeviceVulkan12Features enabled12{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    enabled12.shaderBufferInt64Atomics = VK_TRUE;
    VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    enabled.pNext = &enabled12;
    enabled.features.shaderInt64 = VK_TRUE;
    std::vector<const char *> extensions = options.deviceExtensions;
    VkPhysicalDeviceShaderClockFeaturesKHR enabledClock{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_CLOCK_FEATURES_KHR};
    if (options.shaderClock) {
        if (!hasDeviceExtension(physicalDevice_, VK_KHR_SHADER_CLOCK_EXTENSION_NAME) ||
            !supportedClock.shaderSubgroupClock)
            throw Error(deviceName() + " lacks VK_KHR_shader_clock (subgroup clock), which "
                                       "profiling needs");
        enabledClock.shaderSubgroupClock = VK_TRUE;
        enabled12.pNext = &enabledClock;
        extensions.push_back(VK_KHR_SHADER_CLOCK_EXTENSION_NAME);
        shaderClock_ = true;
    }

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &enabled;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VK_CHECK(vkCreateDevice(physicalDevice_, &info, nullptr, &device_));
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
}

bool Context::hasMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const {
    for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) &&
            (memoryProperties_.memoryTypes[i].propertyFlags & wanted) == wanted)
            return true;
    return false;
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const {
    for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) &&
            (memoryProperties_.memoryTypes[i].propertyFlags & wanted) == wanted)
            return i;
    throw Error(deviceName() + " has no memory type with the properties Prism needs");
}

} // namespace prism::vk
