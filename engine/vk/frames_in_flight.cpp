#include "vk/frames_in_flight.h"

#include <cstdint>

#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {

FramesInFlight::FramesInFlight(const Context &context, uint32_t count)
    : device_(context.device()), queue_(context.queue()) {
    try {
        for (uint32_t i = 0; i < count; ++i) {
            Slot &slot = slots_.emplace_back();
            VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
            poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
            poolInfo.queueFamilyIndex = context.queueFamily();
            VK_CHECK(vkCreateCommandPool(device_, &poolInfo, nullptr, &slot.pool));
            VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
            alloc.commandPool = slot.pool;
            alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
            alloc.commandBufferCount = 1;
            VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &slot.commands));
            VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
            VK_CHECK(vkCreateSemaphore(device_, &semaphoreInfo, nullptr, &slot.imageAcquired));
            VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
            fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT; // the first wait returns at once
            VK_CHECK(vkCreateFence(device_, &fenceInfo, nullptr, &slot.done));
        }
    } catch (...) {
        destroy();
        throw;
    }
}

FramesInFlight::~FramesInFlight() {
    destroy();
}

void FramesInFlight::destroy() {
    if (!slots_.empty())
        vkDeviceWaitIdle(device_); // nothing may still use the semaphores or command buffers
    for (auto it = slots_.rbegin(); it != slots_.rend(); ++it) {
        if (it->done)
            vkDestroyFence(device_, it->done, nullptr);
        if (it->imageAcquired)
            vkDestroySemaphore(device_, it->imageAcquired, nullptr);
        if (it->pool)
            vkDestroyCommandPool(device_, it->pool, nullptr); // frees the command buffer
    }
    slots_.clear();
}

void FramesInFlight::waitCurrent() {
    VK_CHECK(vkWaitForFences(device_, 1, &slots_[current_].done, VK_TRUE, UINT64_MAX));
}

VkCommandBuffer FramesInFlight::begin() {
    Slot &slot = slots_[current_];
    VK_CHECK(vkResetCommandPool(device_, slot.pool, 0));
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(slot.commands, &info));
    return slot.commands;
}

void FramesInFlight::submit(VkSemaphore renderDone) {
    Slot &slot = slots_[current_];
    VK_CHECK(vkEndCommandBuffer(slot.commands));
    // Only the colour writes need the swapchain image: tracing starts before it is acquired.
    VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &slot.imageAcquired;
    info.pWaitDstStageMask = &waitStage;
    info.commandBufferCount = 1;
    info.pCommandBuffers = &slot.commands;
    info.signalSemaphoreCount = 1;
    info.pSignalSemaphores = &renderDone;
    // Reset only now: had acquisition failed, the fence would stay signalled for the next wait.
    VK_CHECK(vkResetFences(device_, 1, &slot.done));
    VK_CHECK(vkQueueSubmit(queue_, 1, &info, slot.done));
    current_ = (current_ + 1) % uint32_t(slots_.size());
}

} // namespace prism::vk
