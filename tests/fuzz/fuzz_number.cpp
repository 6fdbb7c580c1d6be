// libFuzzer target: the number parser every reader uses. Beyond not crashing, a float it
// accepts must be finite, and an integer must read back the same when printed.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "scene/number_parser.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::string_view token(reinterpret_cast<const char *>(data), size);
    prism::ParsedFloat f = prism::parseFloat(token);
    if (f.ok() && !std::isfinite(f.value))
        std::abort(); // the parser promises finite floats
    prism::ParsedInteger i = prism::parseInteger(token);
    if (i.ok()) {
        prism::ParsedInteger again = prism::parseInteger(std::to_string(i.value));
        if (!again.ok() || again.value != i.value)
            std::abort();
    }
    return 0;
}
