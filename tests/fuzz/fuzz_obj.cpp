// libFuzzer target: OBJ text, through the reader every `mesh` line uses. (Triangles written
// inline in a scene go through fuzz_scene.)
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "scene/obj_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    try {
        prism::parseObj(std::string_view(reinterpret_cast<const char *>(data), size), "fuzz.obj");
    } catch (const prism::Error &) {
    }
    return 0;
}
