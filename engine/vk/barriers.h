#pragma once
// Pipeline barriers Prism records more than once.
#include <vulkan/vulkan.h>

namespace prism::vk {

// A whole-image (one mip, one layer, colour) barrier with a layout transition (or none, when
// `from` equals `to`).
void imageBarrier(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

// A global memory barrier: writes of srcAccess in srcStage made visible to dstAccess in
// dstStage (buffers written by one command and read by the next, or by the host).
void memoryBarrier(VkCommandBuffer commands, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

} // namespace prism::vk
