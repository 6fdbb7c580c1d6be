// libFuzzer target: .scene text. Any input must either load or be refused with prism::Error;
// a crash, a leak, a hang or a sanitizer report is a finding. Paths in the text resolve
// against a folder that does not exist, so `mesh` and textures take their error paths.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    try {
        prism::parseScene(std::string_view(reinterpret_cast<const char *>(data), size),
                          "/nonexistent-prism-fuzz/fuzz.scene");
    } catch (const prism::Error &) {
    }
    return 0;
}
