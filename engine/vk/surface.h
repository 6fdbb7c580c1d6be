#pragma once
// A VkSurfaceKHR. Created by the windowing code (GLFW knows the platform), adopted here so the
// engine is its one owner and destroys it before the instance. Move-only.
#include <vulkan/vulkan.h>

namespace prism::vk {

class Surface {
public:
    Surface() = default;
    Surface(VkInstance instance, VkSurfaceKHR adopted) : instance_(instance), surface_(adopted) {}
    ~Surface();
    Surface(Surface &&other) noexcept;
    Surface &operator=(Surface &&other) noexcept;
    Surface(const Surface &) = delete;
    Surface &operator=(const Surface &) = delete;

    VkSurfaceKHR handle() const { return surface_; }

private:
    void release();
    VkInstance instance_ = VK_NULL_HANDLE;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
};

} // namespace prism::vk
