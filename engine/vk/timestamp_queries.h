#pragma once
// A timestamp VkQueryPool of two queries (the start and end of a stretch of GPU work), with the
// conversion of its ticks to milliseconds. Non-copyable; the one owner that destroys the pool.
#include <optional>

#include <vulkan/vulkan.h>

namespace prism::vk {

class Context;

class TimestampQueries {
public:
    explicit TimestampQueries(const Context &context);
    ~TimestampQueries();
    TimestampQueries(const TimestampQueries &) = delete;
    TimestampQueries &operator=(const TimestampQueries &) = delete;

    void recordReset(VkCommandBuffer commands) const;
    void recordStart(VkCommandBuffer commands) const;
    void recordEnd(VkCommandBuffer commands) const;
    // Milliseconds between start and end once the commands have completed; none when the
    // device could not time them.
    std::optional<double> elapsedMs() const;

private:
    VkDevice device_;
    double periodNs_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
};

} // namespace prism::vk
