#pragma once
// A graphics pipeline for fullscreen passes: no vertex input (the vertex shader makes its own
// triangle), dynamic viewport and scissor, no blending; with its descriptor set layout,
// pipeline layout and a single descriptor set, like ComputePipeline.
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/descriptor_set.h"

namespace prism::vk {

class Context;

struct GraphicsPipelineDesc {
    std::span<const uint32_t> vertexSpirv;
    std::span<const uint32_t> fragmentSpirv;
    std::vector<VkDescriptorType> bindings; // fragment stage, binding i, count 1
    std::vector<SpecializationConstant> fragmentSpecialization;
    uint32_t pushConstantBytes = 0;           // fragment stage
    VkRenderPass renderPass = VK_NULL_HANDLE; // subpass 0
};

class GraphicsPipeline {
public:
    GraphicsPipeline(const Context &context, const GraphicsPipelineDesc &desc);
    ~GraphicsPipeline();
    GraphicsPipeline(const GraphicsPipeline &) = delete;
    GraphicsPipeline &operator=(const GraphicsPipeline &) = delete;

    // The caller makes sure no command buffer in flight uses the set.
    void bindStorageImage(uint32_t binding, VkImageView view) {
        set_.writeStorageImage(binding, view);
    }
    // Binds pipeline and descriptor set on `commands`.
    void bind(VkCommandBuffer commands) const;
    VkPipelineLayout layout() const { return layout_; }

private:
    void destroy();
    VkDevice device_;
    DescriptorSet set_;
    VkShaderModule vertex_ = VK_NULL_HANDLE;
    VkShaderModule fragment_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace prism::vk
