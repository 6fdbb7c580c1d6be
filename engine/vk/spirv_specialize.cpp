#include "vk/spirv_specialize.h"

#include <cstring>
#include <unordered_map>

#include <spirv-tools/optimizer.hpp>

#include "cache/content_hash.h"
#include "cache/disk_cache.h"

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

namespace {

// The stored entries' format: a new one when the passes change, so that no module folded by
// other passes is read back. SPIRV-Tools' version is not in the key: any fold of the same module
// with the same constants leaves code that computes the same values, so another version's
// entry serves as well.
constexpr uint32_t kFoldFormat = 1;
constexpr uint32_t kSpirvMagic = 0x07230203;

} // namespace

std::vector<uint32_t> foldSpecializationStored(std::span<const uint32_t> spirv,
                                               const std::vector<SpecializationConstant> &constants,
                                               const DiskCache *store, std::string &error) {
    if (!store)
        return foldSpecialization(spirv, constants, error);
    ContentHash key;
    key.text("prism spirv fold").value(kFoldFormat).bytes(spirv.data(), spirv.size_bytes());
    for (const SpecializationConstant &c : constants)
        key.value(c.id).value(c.value);
    std::string hex = key.hex();
    if (std::optional<CacheEntry> entry = store->load("spirv", hex, kFoldFormat)) {
        std::string_view bytes = entry->payload;
        // The entry's checksum held: a payload that is not a module is an old bug's, refolded.
        if (bytes.size() >= 20 && bytes.size() % 4 == 0) {
            std::vector<uint32_t> folded(bytes.size() / 4);
            std::memcpy(folded.data(), bytes.data(), bytes.size());
            if (folded[0] == kSpirvMagic)
                return folded;
        }
        store->discard("spirv", hex, "not a SPIR-V module");
    }
    std::vector<uint32_t> folded = foldSpecialization(spirv, constants, error);
    if (!folded.empty())
        store->store("spirv", hex, kFoldFormat,
                     std::string_view(reinterpret_cast<const char *>(folded.data()),
                                      folded.size() * sizeof(uint32_t)));
    return folded;
}

} // namespace prism::vk
