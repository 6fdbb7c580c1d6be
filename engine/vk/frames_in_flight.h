#pragma once
// The per-frame objects of a render loop that lets the host record frame N+1 while the GPU
// still works on frame N: for each slot a command pool + buffer, an "image acquired" semaphore
// and a fence signalled when the slot's submission is done. Owner of all of them.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace prism::vk {

class Context;

class FramesInFlight {
public:
    FramesInFlight(const Context &context, uint32_t count);
    ~FramesInFlight();
    FramesInFlight(const FramesInFlight &) = delete;
    FramesInFlight &operator=(const FramesInFlight &) = delete;

    // Blocks until the current slot's previous submission has finished on the GPU; after this
    // its command buffer and semaphore may be reused.
    void waitCurrent();
    // The semaphore to pass to vkAcquireNextImageKHR for this slot.
    VkSemaphore imageAcquired() const { return slots_[current_].imageAcquired; }
    // Resets the slot's command pool and begins its command buffer.
    VkCommandBuffer begin();
    // Ends and submits the command buffer: it waits for imageAcquired() before writing colour
    // attachments and signals `renderDone` and the slot's fence. Then moves to the next slot.
    void submit(VkSemaphore renderDone);
    uint32_t count() const { return uint32_t(slots_.size()); }
    uint32_t current() const { return current_; } // 0..count-1, for per-slot data of callers

private:
    struct Slot {
        VkCommandPool pool = VK_NULL_HANDLE;
        VkCommandBuffer commands = VK_NULL_HANDLE;
        VkSemaphore imageAcquired = VK_NULL_HANDLE;
        VkFence done = VK_NULL_HANDLE;
    };
    void destroy();
    VkDevice device_;
    VkQueue queue_;
    std::vector<Slot> slots_;
    uint32_t current_ = 0;
};

} // namespace prism::vk
