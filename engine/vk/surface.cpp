#include "vk/surface.h"

#include <utility>

namespace prism::vk {

Surface::~Surface() {
    release();
}

Surface::Surface(Surface &&other) noexcept {
    *this = std::move(other);
}

Surface &Surface::operator=(Surface &&other) noexcept {
    if (this != &other) {
        release();
        instance_ = std::exchange(other.instance_, VK_NULL_HANDLE);
        surface_ = std::exchange(other.surface_, VK_NULL_HANDLE);
    }
    return *this;
}

void Surface::release() {
    if (surface_)
        vkDestroySurfaceKHR(instance_, surface_, nullptr);
    surface_ = VK_NULL_HANDLE;
}

} // namespace prism::vk
