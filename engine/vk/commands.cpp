#include "vk/commands.h"

#include <cstdint>

#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {

CommandRunner::CommandRunner(const Context &context)
    : device_(context.device()), queue_(context.queue()) {
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = context.queueFamily();
    VK_CHECK(vkCreateCommandPool(device_, &poolInfo, nullptr, &pool_));

    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    try {
        VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &commands_));
        VK_CHECK(vkCreateFence(device_, &fenceInfo, nullptr, &fence_));
    } catch (...) {
        vkDestroyCommandPool(device_, pool_, nullptr);
        throw;
    }
}

CommandRunner::~CommandRunner() {
    vkDestroyFence(device_, fence_, nullptr);
    vkDestroyCommandPool(device_, pool_, nullptr); // frees the command buffer
}

void CommandRunner::run(const std::function<void(VkCommandBuffer)> &record) {
    VK_CHECK(vkResetCommandBuffer(commands_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands_, &begin));
    record(commands_);
    VK_CHECK(vkEndCommandBuffer(commands_));

    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands_;
    VK_CHECK(vkResetFences(device_, 1, &fence_));
    VK_CHECK(vkQueueSubmit(queue_, 1, &submit, fence_));
    VK_CHECK(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
}

} // namespace prism::vk
