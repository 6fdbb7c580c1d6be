#pragma once
// VK_CHECK: every Vulkan call that can fail throws prism::Error naming the call, file and line.
#include <string>
#include <vulkan/vulkan.h>

#include "core/error.h"

namespace prism::vk {

const char *resultName(VkResult result);

[[noreturn]] void throwVulkanError(VkResult result, const char *call, const char *file, int line);

} // namespace prism::vk

#define VK_CHECK(call)                                                                             \
    do {                                                                                           \
        VkResult vkCheckResult_ = (call);                                                          \
        if (vkCheckResult_ != VK_SUCCESS)                                                          \
            ::prism::vk::throwVulkanError(vkCheckResult_, #call, __FILE__, __LINE__);              \
    } while (0)
