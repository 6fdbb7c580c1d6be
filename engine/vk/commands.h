#pragma once
// A command pool with one primary command buffer and a fence: record, submit, wait.
#include <functional>

#include <vulkan/vulkan.h>

namespace prism::vk {

class Context;

class CommandRunner {
public:
    explicit CommandRunner(const Context &context);
    ~CommandRunner();
    CommandRunner(const CommandRunner &) = delete;
    CommandRunner &operator=(const CommandRunner &) = delete;

    // Records `record` into the command buffer, submits it and blocks until the GPU is done.
    void run(const std::function<void(VkCommandBuffer)> &record);

private:
    VkDevice device_;
    VkQueue queue_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

} // namespace prism::vk
