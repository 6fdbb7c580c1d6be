// libFuzzer target: MTL text (materials, texture statements).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "scene/mtl_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::vector<std::string> warnings;
    try {
        prism::parseMtl(std::string_view(reinterpret_cast<const char *>(data), size), "fuzz.mtl",
                        warnings);
    } catch (const prism::Error &) {
    }
    return 0;
}
