// Stands in for embree_baseline.cpp where libembree-dev is not installed.
#include "embree_baseline.h"

#include "core/error.h"

namespace prism {

struct EmbreeBaseline::State {
    EmbreeBuild build;
};

bool embreeAvailable() {
    return false;
}

EmbreeBaseline::EmbreeBaseline(const Scene &, uint32_t, uint32_t) {
    throw Error("built without Embree: install libembree-dev (tools/scripts/install-deps.sh) "
                "and reconfigure");
}

EmbreeBaseline::~EmbreeBaseline() = default;

const EmbreeBuild &EmbreeBaseline::build() const {
    return state_->build; // never called: construction throws
}

EmbreeFrame EmbreeBaseline::traceFrame() {
    return {};
}

} // namespace prism
