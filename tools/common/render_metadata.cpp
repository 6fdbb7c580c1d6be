#include "render_metadata.h"

namespace prism {

ImageMetadata renderMetadata(const RenderRecord &r) {
    ImageMetadata meta;
    meta.strings = {{"prism:commandLine", r.commandLine},
                    {"prism:scene", r.scenePath},
                    {"prism:device", r.device},
                    {"prism:backend", r.backend},
                    {"prism:gridResolution", r.gridResolution},
                    {"prism:gridChoice", r.gridChoice},
                    {"prism:gridCells", std::to_string(r.gridCells)},
                    {"prism:gridBytes", std::to_string(r.gridBytes)},
                    {"prism:raysPrimary", std::to_string(r.rays.primary)},
                    {"prism:raysShadow", std::to_string(r.rays.shadow)},
                    {"prism:raysSecondary", std::to_string(r.rays.secondary)}};
    meta.floats = {{"prism:renderTimeMs", float(r.renderTimeMs)},
                   {"prism:renderTimeMedianMs", float(r.renderTimeMedianMs)},
                   {"prism:gridBuildMs", float(r.gridBuildMs)},
                   {"prism:gridCellsPerPrimaryRay", float(r.gridCellsPerPrimaryRay)},
                   {"prism:gridTestsPerPrimaryRay", float(r.gridTestsPerPrimaryRay)},
                   {"prism:mraysPerSecond", float(r.mraysPerSecond)}};
    meta.ints = {{"prism:samplesPerPixel", int(r.samplesPerPixel)},
                 {"prism:maxDepth", int(r.maxDepth)},
                 {"prism:seed", int(r.seed)}};
    if (r.frame >= 0)
        meta.ints.emplace_back("prism:frame", r.frame);
    if (!r.region.empty())
        meta.strings.emplace_back("prism:region", r.region);
    if (!r.tile.empty())
        meta.strings.emplace_back("prism:tile", r.tile);
    return meta;
}

} // namespace prism
