#pragma once
// Specialization constants folded into a SPIR-V module on the host, before the driver sees it.
//
// A driver folds specialization constants only after it has translated the whole module, and
// lavapipe's translation (SPIR-V to NIR, every function inlined) costs far more than the
// module's size: the tracer, 191 KB with everything a scene could use, took 120-300 ms to become
// a pipeline whatever the constants switched off. SPIRV-Tools' optimizer sets the constants'
// values, freezes them into plain constants, and removes the branches and functions they make
// dead; the driver then translates only what the scene uses (docs/benchmarks.md, "Specialization
// folded on the host"). Only dead code goes: no arithmetic is rewritten, so the pipeline computes
// the same values to the bit.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "vk/descriptor_set.h"

namespace prism {
class DiskCache;
}

namespace prism::vk {

// `spirv` with `constants` (32-bit values: bools as 0 or 1, floats as their bits) folded in and
// the code they make unreachable removed. Empty when the optimizer fails (`error` then says why);
// the caller may still use `spirv` with the constants as specialization info.
std::vector<uint32_t> foldSpecialization(std::span<const uint32_t> spirv,
                                         const std::vector<SpecializationConstant> &constants,
                                         std::string &error);

// The same through `store` where there is one: a module folded before with the same constants
// (kind "spirv", keyed by the module's words and the constants) is read back instead of folded
// again (28-35 ms for the tracer), and a new fold is stored.
std::vector<uint32_t> foldSpecializationStored(std::span<const uint32_t> spirv,
                                               const std::vector<SpecializationConstant> &constants,
                                               const DiskCache *store, std::string &error);

} // namespace prism::vk
