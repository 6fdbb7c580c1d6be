// Stands in for embree_baseline.cpp where libembree-dev is not installed.
#include "embree_baseline.h"

#include "core/error.h"

namespace prism {

struct EmbreeBaseline::State {};

bool embreeAvailable() {
    return false;
}

EmbreeBaseline::EmbreeBaseline(const Scene &, uint32_t, uint32_t) {
    throw Error("built without Embree: install libembree-dev (tools/scripts/install-deps.sh) "
                "and reconfigure");
}

EmbreeBaseline::~EmbreeBaseline() = default;

// Never reached: there is no object to call them on, construction throws.
const EmbreeBuild &EmbreeBaseline::build() const {
    throw Error("built without Embree");
}

EmbreeFrame EmbreeBaseline::traceFrame() {
    throw Error("built without Embree");
}

} // namespace prism
