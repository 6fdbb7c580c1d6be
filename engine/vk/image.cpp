#include "vk/image.h"

#include <utility>

#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {

bool Image::hostReadableSupported(const Context &context, uint32_t width, uint32_t height,
                                  VkFormat format, VkImageUsageFlags usage) {
    VkImageFormatProperties properties;
    if (vkGetPhysicalDeviceImageFormatProperties(context.physicalDevice(), format, VK_IMAGE_TYPE_2D,
                                                 VK_IMAGE_TILING_LINEAR, usage, 0,
                                                 &properties) != VK_SUCCESS)
        return false;
    // Linear images may have smaller limits than optimal ones; 16 bytes a texel at most here.
    if (width > properties.maxExtent.width || height > properties.maxExtent.height ||
        VkDeviceSize(width) * height * 16 > properties.maxResourceSize)
        return false;
    return context.hasMemoryType(~0u, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                          VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
}

Image::Image(const Context &context, uint32_t width, uint32_t height, VkFormat format,
             VkImageUsageFlags usage, bool hostReadable)
    : device_(context.device()), format_(format), width_(width), height_(height) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = hostReadable ? VK_IMAGE_TILING_LINEAR : VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(device_, &info, nullptr, &image_));
    try {
        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(device_, image_, &requirements);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = requirements.size;
        alloc.memoryTypeIndex = context.findMemoryType(
            requirements.memoryTypeBits, hostReadable ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                            VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                                      : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        VK_CHECK(vkAllocateMemory(device_, &alloc, nullptr, &memory_));
        VK_CHECK(vkBindImageMemory(device_, image_, memory_, 0));
        if (hostReadable) {
            VkImageSubresource texels{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0};
            VkSubresourceLayout layout;
            vkGetImageSubresourceLayout(device_, image_, &texels, &layout);
            void *memory = nullptr;
            VK_CHECK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &memory));
            mapped_ = static_cast<const std::byte *>(memory) + layout.offset;
            rowPitch_ = size_t(layout.rowPitch);
        }

        VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        viewInfo.image = image_;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = format;
        viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VK_CHECK(vkCreateImageView(device_, &viewInfo, nullptr, &view_));
    } catch (...) {
        release();
        throw;
    }
}

Image::~Image() {
    release();
}

Image::Image(Image &&other) noexcept {
    *this = std::move(other);
}

Image &Image::operator=(Image &&other) noexcept {
    if (this != &other) {
        release();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        image_ = std::exchange(other.image_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
        format_ = other.format_;
        width_ = other.width_;
        height_ = other.height_;
        mapped_ = std::exchange(other.mapped_, nullptr);
        rowPitch_ = other.rowPitch_;
    }
    return *this;
}

void Image::release() {
    if (view_)
        vkDestroyImageView(device_, view_, nullptr);
    if (image_)
        vkDestroyImage(device_, image_, nullptr);
    if (memory_)
        vkFreeMemory(device_, memory_, nullptr);
    view_ = VK_NULL_HANDLE;
    image_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr; // unmapped with its memory
}

} // namespace prism::vk
