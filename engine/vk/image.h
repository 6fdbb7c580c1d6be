#pragma once
// A 2D VkImage with its memory and one view. Move-only owner.
#include <cstddef>

#include <vulkan/vulkan.h>

namespace prism::vk {

class Context;

class Image {
public:
    Image() = default;
    // With `hostReadable`, the host reads the image in place instead of from a copy: linear
    // tiling in host-visible, coherent memory, mapped while the image lives. Only where
    // hostReadableSupported says the device has it for the size, format and usage.
    Image(const Context &context, uint32_t width, uint32_t height, VkFormat format,
          VkImageUsageFlags usage, bool hostReadable = false);
    static bool hostReadableSupported(const Context &context, uint32_t width, uint32_t height,
                                      VkFormat format, VkImageUsageFlags usage);
    ~Image();
    Image(Image &&other) noexcept;
    Image &operator=(Image &&other) noexcept;
    Image(const Image &) = delete;
    Image &operator=(const Image &) = delete;

    VkImage handle() const { return image_; }
    VkImageView view() const { return view_; }
    VkFormat format() const { return format_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    // A host-readable image's texels (null otherwise): row y at mapped() + y * rowPitch(), in
    // the GENERAL layout once the device's writes are made visible to the host.
    const std::byte *mapped() const { return mapped_; }
    size_t rowPitch() const { return rowPitch_; }

private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    uint32_t width_ = 0, height_ = 0;
    const std::byte *mapped_ = nullptr;
    size_t rowPitch_ = 0;
};

} // namespace prism::vk
