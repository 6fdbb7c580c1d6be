#include "accel/grid_choice.h"

#include <cstdio>
#include <optional>
#include <string>

namespace prism {
namespace {

// The lattice of rays is 4:3; the render's own size is not known when the grid is built.
constexpr double kChoiceAspect = 4.0 / 3.0;
constexpr int kChoiceColumns = 48;

// Counting the regular grid stops here: far above any cost the adaptive grid has shown, so
// the choice is already clear (the teapot in the stadium would count 6,320 tests a ray).
constexpr double kStopCountingAbove = 200.0;

std::string describe(const char *name, const WalkCounts &counts, double cost) {
    char text[160];
    const char *atLeast = counts.stopped ? ">= " : "";
    std::snprintf(text, sizeof text, "%s %s%.1f (%s%.2f cells, %s%.2f tests a ray)", name, atLeast,
                  cost, atLeast, counts.cellsPerRay, atLeast, counts.testsPerRay);
    return text;
}

// The tracer's work per ray, in primitive tests.
double walkCost(const WalkCounts &counts, bool adaptive) {
    return counts.testsPerRay +
           counts.cellsPerRay * (adaptive ? kAdaptiveStepCost : kRegularStepCost);
}

} // namespace

Grid chooseGrid(const Scene &scene, const std::function<Grid(GridOptions::Mode)> &build,
                const std::function<Grid()> &regularLayout) {
    std::optional<Grid> adaptive;
    WalkCounts adaptiveCounts;
    double adaptiveCost = 0.0;
    auto buildAdaptive = [&] {
        adaptive = build(GridOptions::Mode::Adaptive);
        adaptiveCounts = countWalks(scene, *adaptive, kChoiceAspect, kChoiceColumns);
        adaptiveCost = walkCost(adaptiveCounts, true);
    };
    if (scene.finitePrimitiveCount() >= kAdaptiveFirstFrom) {
        // The regular grid costs at least `bound`. Where even that is not low and the adaptive
        // grid beats it by the margin, the regular grid's own counts could only widen the gap:
        // the rules below would choose the adaptive grid too.
        buildAdaptive();
        WalkCounts bound = lowerBoundWalks(scene, regularLayout(), kChoiceAspect, kChoiceColumns,
                                           adaptiveCounts.nearestHits);
        double boundCost = walkCost(bound, false);
        if (boundCost >= kConsiderAdaptiveCost && adaptiveCost < kAdaptiveMargin * boundCost) {
            adaptive->choice = "adaptive: cost " +
                               describe("adaptive", adaptiveCounts, adaptiveCost) + " against " +
                               describe("regular", bound, boundCost) + " (not built)";
            return std::move(*adaptive);
        }
    }
    Grid regular = build(GridOptions::Mode::Regular);
    if (scene.finitePrimitiveCount() == 0) {
        regular.choice = "regular (nothing to grid)";
        return regular;
    }
    WalkCounts regularCounts =
        countWalks(scene, regular, kChoiceAspect, kChoiceColumns, kStopCountingAbove);
    double regularCost = walkCost(regularCounts, false);
    std::string regularText = describe("regular", regularCounts, regularCost);
    if (regularCost < kConsiderAdaptiveCost) {
        regular.choice = "regular: cost " + regularText + " is low";
        return regular;
    }
    if (!adaptive)
        buildAdaptive();
    std::string both =
        describe("adaptive", adaptiveCounts, adaptiveCost) + " against " + regularText;
    if (adaptiveCost < kAdaptiveMargin * regularCost) {
        adaptive->choice = "adaptive: cost " + both;
        return std::move(*adaptive);
    }
    regular.choice = "regular: cost " + both;
    return regular;
}

} // namespace prism
