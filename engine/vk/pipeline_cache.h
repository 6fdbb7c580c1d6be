#pragma once
// The device's VkPipelineCache, kept on disk between runs beside the grid cache
// (cache/disk_cache.h, entries `pipelines-KEY.bin`). Creating the tracer's pipelines is the
// largest part of a GPU's first image when the driver has not seen the shader (30-400 ms on an
// H200, issue 31); a driver that honours the cache skips that work the second time. lavapipe's
// cache is a 32-byte header (Mesa's own shader disk cache serves it instead), so there this
// costs a few microseconds and saves nothing.
//
// The key is the device's identity (vendor, device, driver version, pipelineCacheUUID), so an
// entry is never offered to another driver; the driver checks the data's own header too.
#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

namespace prism {
class DiskCache;
}

namespace prism::vk {

class Context;

class PipelineCache {
public:
    // Empty, or seeded with what `store` kept for this device.
    PipelineCache(const Context &context, const DiskCache *store);
    ~PipelineCache();
    PipelineCache(const PipelineCache &) = delete;
    PipelineCache &operator=(const PipelineCache &) = delete;

    VkPipelineCache handle() const { return cache_; }
    uint64_t loadedBytes() const { return loaded_.size(); }
    const DiskCache *store() const { return store_; }
    // Writes the cache's data to the store when it changed since it was loaded; the bytes
    // written (0 when unchanged or without a store). Never throws.
    uint64_t save();

private:
    VkDevice device_;
    const DiskCache *store_;
    std::string key_;
    std::string loaded_;
    VkPipelineCache cache_ = VK_NULL_HANDLE;
};

// The key of a device's entry: a digest of its vendor, device, driver version and cache UUID.
std::string pipelineCacheKey(const VkPhysicalDeviceProperties &properties);

} // namespace prism::vk
