// Stands in for embree_build.cpp where libembree-dev is not installed.
#include "embree_build.h"

#include "core/error.h"

namespace prism {

bool embreeAvailable() {
    return false;
}

EmbreeBuild timeEmbreeBuild(const Scene &) {
    throw Error("prism-gridbench was built without Embree (install libembree-dev and rebuild)");
}

} // namespace prism
