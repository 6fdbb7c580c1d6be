#include "vk/swapchain.h"

#include <algorithm>

#include "core/error.h"
#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {
namespace {

VkSurfaceFormatKHR chooseFormat(const std::vector<VkSurfaceFormatKHR> &formats) {
    // sRGB formats let the hardware encode; the present shader encodes for the UNORM ones.
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB,
                            VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
        for (const VkSurfaceFormatKHR &f : formats)
            if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
                return f;
    return formats.front();
}

VkPresentModeKHR choosePresentMode(const std::vector<VkPresentModeKHR> &modes, bool vsync) {
    if (!vsync) // MAILBOX never tears; IMMEDIATE may, but neither blocks on the display
        for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
            if (std::find(modes.begin(), modes.end(), wanted) != modes.end())
                return wanted;
    return VK_PRESENT_MODE_FIFO_KHR; // the one mode every surface has
}

bool isSrgb(VkFormat format) {
    return format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_R8G8B8A8_SRGB ||
           format == VK_FORMAT_A8B8G8R8_SRGB_PACK32;
}

} // namespace

const char *presentModeName(VkPresentModeKHR mode) {
    switch (mode) {
    case VK_PRESENT_MODE_IMMEDIATE_KHR:
        return "immediate";
    case VK_PRESENT_MODE_MAILBOX_KHR:
        return "mailbox";
    case VK_PRESENT_MODE_FIFO_KHR:
        return "fifo";
    case VK_PRESENT_MODE_FIFO_RELAXED_KHR:
        return "fifo-relaxed";
    default:
        return "other";
    }
}

Swapchain::Swapchain(const Context &context, VkSurfaceKHR surface, const SwapchainOptions &options)
    : device_(context.device()) {
    VkPhysicalDevice gpu = context.physicalDevice();
    VkBool32 canPresent = VK_FALSE;
    VK_CHECK(
        vkGetPhysicalDeviceSurfaceSupportKHR(gpu, context.queueFamily(), surface, &canPresent));
    if (!canPresent)
        throw Error(context.deviceName() + " cannot present to this window from its compute and "
                                           "graphics queue");

    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu, surface, &caps));
    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, formats.data()));
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(gpu, surface, &count, nullptr));
    std::vector<VkPresentModeKHR> modes(count);
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(gpu, surface, &count, modes.data()));
    if (formats.empty() || modes.empty())
        throw Error("the window's surface offers no formats or present modes");

    VkSurfaceFormatKHR format = chooseFormat(formats);
    format_ = format.format;
    encodesSrgb_ = isSrgb(format_);
    presentMode_ = choosePresentMode(modes, options.vsync);
    // 0xFFFFFFFF: the surface takes the swapchain's size, so we pick it (within the limits).
    extent_ = caps.currentExtent;
    if (extent_.width == UINT32_MAX) {
        extent_.width =
            std::clamp(options.extent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent_.height = std::clamp(options.extent.height, caps.minImageExtent.height,
                                    caps.maxImageExtent.height);
    }
    // One more than the minimum so acquiring never waits for the driver's own use.
    uint32_t imageCount = caps.minImageCount + 1;
    if (caps.maxImageCount != 0)
        imageCount = std::min(imageCount, caps.maxImageCount);

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = imageCount;
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR))
        info.compositeAlpha = VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
    info.presentMode = presentMode_;
    info.clipped = VK_TRUE;
    info.oldSwapchain = options.previous;
    VK_CHECK(vkCreateSwapchainKHR(device_, &info, nullptr, &swapchain_));
    try {
        VK_CHECK(vkGetSwapchainImagesKHR(device_, swapchain_, &count, nullptr));
        images_.resize(count);
        VK_CHECK(vkGetSwapchainImagesKHR(device_, swapchain_, &count, images_.data()));
        for (VkImage image : images_) {
            VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
            viewInfo.image = image;
            viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
            viewInfo.format = format_;
            viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            VkImageView view = VK_NULL_HANDLE;
            VK_CHECK(vkCreateImageView(device_, &viewInfo, nullptr, &view));
            views_.push_back(view);
            VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
            VkSemaphore semaphore = VK_NULL_HANDLE;
            VK_CHECK(vkCreateSemaphore(device_, &semaphoreInfo, nullptr, &semaphore));
            renderDone_.push_back(semaphore);
        }
    } catch (...) {
        destroy();
        throw;
    }
}

Swapchain::~Swapchain() {
    destroy();
}

void Swapchain::destroy() {
    for (VkSemaphore semaphore : renderDone_)
        vkDestroySemaphore(device_, semaphore, nullptr);
    for (VkImageView view : views_)
        vkDestroyImageView(device_, view, nullptr);
    renderDone_.clear();
    views_.clear();
    images_.clear();
    if (swapchain_)
        vkDestroySwapchainKHR(device_, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
}

} // namespace prism::vk
