#include "vk/spirv_specialize.h"

#include <unordered_map>

#include <spirv-tools/optimizer.hpp>

namespace prism::vk {

std::vector<uint32_t> foldSpecialization(std::span<const uint32_t> spirv,
                                         const std::vector<SpecializationConstant> &constants,
                                         std::string &error) {
    std::unordered_map<uint32_t, std::vector<uint32_t>> values;
    for (const SpecializationConstant &c : constants)
        values[c.id] = {c.value};
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
    optimizer.SetMessageConsumer([&error](spv_message_level_t level, const char *,
                                          const spv_position_t &position, const char *message) {
        if (level <= SPV_MSG_ERROR)
            error += "SPIR-V word " + std::to_string(position.index) + ": " + message + "\n";
    });
    // The values in, then made plain constants, and what they decide folded: a condition on
    // them becomes true or false (conditional constant propagation), its dead branch and the
    // functions only it called go, and with them the code that fed only them.
    optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values))
        .RegisterPass(spvtools::CreateFreezeSpecConstantValuePass())
        .RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass())
        .RegisterPass(spvtools::CreateCCPPass())
        .RegisterPass(spvtools::CreateDeadBranchElimPass())
        .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
        .RegisterPass(spvtools::CreateAggressiveDCEPass());
    spvtools::OptimizerOptions options;
    // The modules are glslang's, checked when they were built, and the validation layers check
    // the result in tests and debug builds; validating here would cost as much as the passes.
    options.set_run_validator(false);
    std::vector<uint32_t> folded;
    if (!optimizer.Run(spirv.data(), spirv.size(), &folded, options)) {
        if (error.empty())
            error = "the SPIR-V optimizer failed";
        return {};
    }
    return folded;
}

} // namespace prism::vk
