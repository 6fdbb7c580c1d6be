#pragma once
// A VkSwapchainKHR with a view and a "rendering done" semaphore per image. Recreate it (resize,
// out of date) by building a new one with the old one's handle, then dropping the old one.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace prism::vk {

class Context;

struct SwapchainOptions {
    VkExtent2D extent{0, 0}; // used when the surface leaves the size to us
    bool vsync = true;       // false: MAILBOX or IMMEDIATE where the surface has one
    VkSwapchainKHR previous = VK_NULL_HANDLE;
};

class Swapchain {
public:
    Swapchain(const Context &context, VkSurfaceKHR surface, const SwapchainOptions &options);
    ~Swapchain();
    Swapchain(const Swapchain &) = delete;
    Swapchain &operator=(const Swapchain &) = delete;

    VkSwapchainKHR handle() const { return swapchain_; }
    VkFormat format() const { return format_; }
    // True when the format is *_SRGB: the hardware encodes on write, shaders output linear.
    bool encodesSrgb() const { return encodesSrgb_; }
    VkExtent2D extent() const { return extent_; }
    VkPresentModeKHR presentMode() const { return presentMode_; }
    uint32_t imageCount() const { return uint32_t(images_.size()); }
    VkImage image(uint32_t i) const { return images_[i]; }
    VkImageView view(uint32_t i) const { return views_[i]; }
    // Signalled by the frame that draws image i, waited on by its present. One per image, not
    // per frame in flight: the presentation engine may hold it until the image comes back.
    VkSemaphore renderDone(uint32_t i) const { return renderDone_[i]; }

private:
    void destroy();
    VkDevice device_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    bool encodesSrgb_ = false;
    VkExtent2D extent_{0, 0};
    VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
    std::vector<VkImage> images_; // owned by the swapchain itself
    std::vector<VkImageView> views_;
    std::vector<VkSemaphore> renderDone_;
};

const char *presentModeName(VkPresentModeKHR mode);

} // namespace prism::vk
