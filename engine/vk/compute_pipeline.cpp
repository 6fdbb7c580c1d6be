#include "vk/compute_pipeline.h"

#include <string>

#include "vk/context.h"
#include "vk/spirv_specialize.h"
#include "vk/vk_check.h"

namespace prism::vk {

ComputePipeline::ComputePipeline(const Context &context, const ComputePipelineDesc &desc)
    : device_(context.device()), set_(device_, desc.bindings, VK_SHADER_STAGE_COMPUTE_BIT) {
    try {
        // The constants folded into the module first (vk/spirv_specialize.h); should that fail,
        // the driver gets the module as it is, with the constants as specialization info.
        std::vector<uint32_t> folded;
        if (desc.foldSpecialization && !desc.specialization.empty()) {
            std::string error;
            folded =
                foldSpecializationStored(desc.spirv, desc.specialization, context.store(), error);
            folded_ = !folded.empty();
        }
        std::span<const uint32_t> spirv = folded_ ? std::span<const uint32_t>(folded) : desc.spirv;
        module_ = createShaderModule(device_, spirv.data(), spirv.size_bytes());

        VkDescriptorSetLayout setLayout = set_.layout();
        VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, desc.pushConstantBytes};
        VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layoutInfo.setLayoutCount = 1;
        layoutInfo.pSetLayouts = &setLayout;
        layoutInfo.pushConstantRangeCount = desc.pushConstantBytes ? 1 : 0;
        layoutInfo.pPushConstantRanges = &range;
        VK_CHECK(vkCreatePipelineLayout(device_, &layoutInfo, nullptr, &layout_));

        SpecializationData specialization(desc.specialization);
        VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        pipelineInfo.stage.module = module_;
        pipelineInfo.stage.pName = "main";
        pipelineInfo.stage.pSpecializationInfo = specialization.pointer();
        pipelineInfo.layout = layout_;
        VK_CHECK(vkCreateComputePipelines(device_, context.pipelineCache(), 1, &pipelineInfo,
                                          nullptr, &pipeline_));
    } catch (...) {
        destroy();
        throw;
    }
}

ComputePipeline::~ComputePipeline() {
    destroy();
}

void ComputePipeline::destroy() {
    if (pipeline_)
        vkDestroyPipeline(device_, pipeline_, nullptr);
    if (layout_)
        vkDestroyPipelineLayout(device_, layout_, nullptr);
    if (module_)
        vkDestroyShaderModule(device_, module_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    module_ = VK_NULL_HANDLE;
}

void ComputePipeline::bind(VkCommandBuffer commands) const {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_.handle(),
                            0, nullptr);
}

} // namespace prism::vk
