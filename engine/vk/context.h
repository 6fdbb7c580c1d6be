#pragma once
// The Vulkan instance, the chosen physical device, its logical device and compute queue.
// One owner for each; destroyed in reverse creation order.
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace prism {
class DiskCache;
}

namespace prism::vk {

class PipelineCache;

struct ContextOptions {
    bool validation = false;                      // Khronos validation layer + debug messenger
    std::vector<const char *> instanceExtensions; // e.g. what GLFW needs for a surface
    std::vector<const char *> deviceExtensions;   // e.g. VK_KHR_swapchain
    std::string deviceNameFilter; // choose the first device whose name contains this
    // VK_KHR_shader_clock's subgroup clock, which the profiling tracer reads (prism-bench
    // --profile); a device without it is refused by name.
    bool shaderClock = false;
    // Where the pipeline cache is kept between runs (vk/pipeline_cache.h); none: in memory only.
    const DiskCache *pipelineStore = nullptr;
};

class Context {
public:
    explicit Context(const ContextOptions &options);
    ~Context();
    Context(const Context &) = delete;
    Context &operator=(const Context &) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamily() const { return queueFamily_; }
    const VkPhysicalDeviceProperties &properties() const { return properties_; }
    std::string deviceName() const { return properties_.deviceName; }
    // lavapipe silently cuts shader loops short after 65,535 iterations (see docs/design.md).
    bool isLavapipe() const { return driverId_ == VK_DRIVER_ID_MESA_LLVMPIPE; }
    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const;
    // Whether typeBits hold a type with every flag of `wanted`.
    bool hasMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const;
    // A CPU device (lavapipe) or an integrated GPU: its device-local memory is the host's, so
    // writing a buffer in place costs no more than writing a staging copy of it.
    bool sharesHostMemory() const {
        return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ||
               properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU;
    }

    // Validation messages seen so far (warnings and errors); tests require zero.
    uint32_t validationMessageCount() const { return validationMessages_.load(); }
    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }
    bool shaderClockEnabled() const { return shaderClock_; }
    // The cache every pipeline of this device is created through.
    VkPipelineCache pipelineCache() const;
    // Writes the pipeline cache to ContextOptions::pipelineStore if it changed; bytes written.
    uint64_t savePipelineCache() const;
    uint64_t pipelineCacheLoadedBytes() const;
    // ContextOptions::pipelineStore: where pipelines keep what they make between runs (the
    // driver's cache, folded modules), or null.
    const DiskCache *store() const;

private:
    void destroy();
    void createInstance(const ContextOptions &options);
    void pickPhysicalDevice(const ContextOptions &options);
    void createDevice(const ContextOptions &options);
    static VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(
        VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
        const VkDebugUtilsMessengerCallbackDataEXT *data, void *user);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memoryProperties_{};
    VkDriverId driverId_{};
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    bool shaderClock_ = false;
    std::atomic<uint32_t> validationMessages_{0};
    std::unique_ptr<PipelineCache> pipelineCache_; // destroyed before the device
};

} // namespace prism::vk
