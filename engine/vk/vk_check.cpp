#include "vk/vk_check.h"

namespace prism::vk {

const char *resultName(VkResult result) {
    switch (result) {
#define PRISM_CASE(r)                                                                              \
    case r:                                                                                        \
        return #r;
        PRISM_CASE(VK_NOT_READY)
        PRISM_CASE(VK_TIMEOUT)
        PRISM_CASE(VK_INCOMPLETE)
        PRISM_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        PRISM_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        PRISM_CASE(VK_ERROR_INITIALIZATION_FAILED)
        PRISM_CASE(VK_ERROR_DEVICE_LOST)
        PRISM_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        PRISM_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        PRISM_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        PRISM_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        PRISM_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        PRISM_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        PRISM_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        PRISM_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        PRISM_CASE(VK_ERROR_SURFACE_LOST_KHR)
        PRISM_CASE(VK_ERROR_OUT_OF_DATE_KHR)
        PRISM_CASE(VK_SUBOPTIMAL_KHR)
#undef PRISM_CASE
    default:
        return "VkResult";
    }
}

void throwVulkanError(VkResult result, const char *call, const char *file, int line) {
    throw Error(std::string("Vulkan call failed with ") + resultName(result) + " (" +
                std::to_string(static_cast<int>(result)) + "): " + call + " at " + file + ":" +
                std::to_string(line));
}

} // namespace prism::vk
