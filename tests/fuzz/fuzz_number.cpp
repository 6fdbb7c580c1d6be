// libFuzzer target: the number parser every reader uses. Beyond not crashing, a float it
// accepts must be finite, a position (parseDouble) must be accepted exactly when the float is
// and lie within the float's range, and an integer must read back the same when printed.
#include <cfloat>
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
    prism::ParsedDouble d = prism::parseDouble(token);
    if (d.ok() != f.ok() || (d.ok() && !(std::fabs(d.value) <= double(FLT_MAX))))
        std::abort(); // same grammar and range as a float
    if (d.ok() && std::fabs(double(f.value) - d.value) > 1e-6 * std::fabs(d.value) + 1e-37)
        std::abort(); // the float is the double, rounded
    prism::ParsedInteger i = prism::parseInteger(token);
    if (i.ok()) {
        prism::ParsedInteger again = prism::parseInteger(std::to_string(i.value));
        if (!again.ok() || again.value != i.value)
            std::abort();
    }
    return 0;
}
