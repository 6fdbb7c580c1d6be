#include "vk/timestamp_queries.h"

#include <cstdint>

#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {

TimestampQueries::TimestampQueries(const Context &context)
    : device_(context.device()), periodNs_(context.properties().limits.timestampPeriod) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2;
    VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &pool_));
}

TimestampQueries::~TimestampQueries() {
    vkDestroyQueryPool(device_, pool_, nullptr);
}

void TimestampQueries::recordReset(VkCommandBuffer commands) const {
    vkCmdResetQueryPool(commands, pool_, 0, 2);
}

void TimestampQueries::recordStart(VkCommandBuffer commands) const {
    vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_, 0);
}

void TimestampQueries::recordEnd(VkCommandBuffer commands) const {
    vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, 1);
}

std::optional<double> TimestampQueries::elapsedMs() const {
    uint64_t ticks[2] = {0, 0};
    VkResult result = vkGetQueryPoolResults(device_, pool_, 0, 2, sizeof(ticks), ticks,
                                            sizeof(uint64_t), VK_QUERY_RESULT_64_BIT);
    if (result != VK_SUCCESS || ticks[1] <= ticks[0])
        return std::nullopt;
    return double(ticks[1] - ticks[0]) * periodNs_ * 1e-6;
}

} // namespace prism::vk
