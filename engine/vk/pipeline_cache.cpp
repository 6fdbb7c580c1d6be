#include "vk/pipeline_cache.h"

#include "cache/content_hash.h"
#include "cache/disk_cache.h"
#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {
namespace {

constexpr uint32_t kPipelineCacheFormat = 1; // our entry's layout: the driver's bytes as they are

} // namespace

std::string pipelineCacheKey(const VkPhysicalDeviceProperties &p) {
    ContentHash hash;
    hash.text("prism pipelines").value(p.vendorID).value(p.deviceID).value(p.driverVersion);
    hash.bytes(p.pipelineCacheUUID, VK_UUID_SIZE);
    return hash.hex();
}

PipelineCache::PipelineCache(const Context &context, const DiskCache *store)
    : device_(context.device()), store_(store) {
    if (store_) {
        key_ = pipelineCacheKey(context.properties());
        if (std::optional<CacheEntry> entry = store_->load("pipelines", key_, kPipelineCacheFormat))
            loaded_ = std::string(entry->payload);
    }
    VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    info.initialDataSize = loaded_.size();
    info.pInitialData = loaded_.empty() ? nullptr : loaded_.data();
    VK_CHECK(vkCreatePipelineCache(device_, &info, nullptr, &cache_));
}

PipelineCache::~PipelineCache() {
    if (cache_)
        vkDestroyPipelineCache(device_, cache_, nullptr);
}

uint64_t PipelineCache::save() {
    if (!store_)
        return 0;
    size_t size = 0;
    if (vkGetPipelineCacheData(device_, cache_, &size, nullptr) != VK_SUCCESS || size == 0)
        return 0;
    std::string data(size, '\0');
    if (vkGetPipelineCacheData(device_, cache_, &size, data.data()) != VK_SUCCESS)
        return 0;
    data.resize(size);
    if (data == loaded_)
        return 0;
    store_->store("pipelines", key_, kPipelineCacheFormat, data);
    loaded_ = std::move(data);
    return loaded_.size();
}

} // namespace prism::vk
