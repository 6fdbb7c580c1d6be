#pragma once
// A compute pipeline with its descriptor set layout, pipeline layout and a single descriptor
// set (one frame in flight for compute is enough: the host waits for each frame).
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/descriptor_set.h"

namespace prism::vk {

class Context;

struct ComputePipelineDesc {
    std::span<const uint32_t> spirv;
    std::vector<VkDescriptorType> bindings; // binding i has type bindings[i], count 1
    std::vector<SpecializationConstant> specialization;
    uint32_t pushConstantBytes = 0;
    // Fold the specialization constants into the module on the host (vk/spirv_specialize.h):
    // the driver then translates only the code they leave live. Off only to compare the two.
    bool foldSpecialization = true;
};

class ComputePipeline {
public:
    ComputePipeline(const Context &context, const ComputePipelineDesc &desc);
    ~ComputePipeline();
    ComputePipeline(const ComputePipeline &) = delete;
    ComputePipeline &operator=(const ComputePipeline &) = delete;

    void bindBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize size = VK_WHOLE_SIZE) {
        set_.writeBuffer(binding, buffer, size);
    }
    void bindStorageImage(uint32_t binding, VkImageView view) {
        set_.writeStorageImage(binding, view);
    }
    void bindTexelBuffer(uint32_t binding, VkBufferView view) {
        set_.writeTexelBuffer(binding, view);
    }
    // Binds pipeline and descriptor set on `commands`.
    void bind(VkCommandBuffer commands) const;
    VkPipelineLayout layout() const { return layout_; }
    // Whether the driver got the module with the specialization folded in (else as it was).
    bool folded() const { return folded_; }

private:
    void destroy();
    VkDevice device_;
    DescriptorSet set_;
    VkShaderModule module_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    bool folded_ = false;
};

} // namespace prism::vk
