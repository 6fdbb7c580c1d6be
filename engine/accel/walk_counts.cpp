#include "accel/walk_counts.h"

#include <algorithm>
#include <limits>
#include <string>

#include "accel/grid_walk.h"
#include "core/error.h"
#include "reference/camera_model.h"
#include "reference/intersect_reference.h"
#include "scene/camera_frame.h"
#include "scene/primitive_ids.h"

namespace prism {
namespace {

// The lattice of camera rays: the pixel centres of a `columns` wide image of the given aspect
// (width / height), numbered row by row. countWalks and lowerBoundWalks walk the same rays in
// the same order, so that one's nearest hits are the other's.
class RayLattice {
public:
    RayLattice(const Camera &camera, double aspect, int columns)
        : width_(columns), height_(std::max(1, int(double(columns) / aspect + 0.5))),
          frame_(makeCameraFrame(camera, width_, height_)) {}
    size_t count() const { return size_t(width_) * size_t(height_); }
    Ray ray(size_t i) const {
        return cameraRay(
            frame_, glm::dvec2(double(i % size_t(width_)) + 0.5, double(i / size_t(width_)) + 0.5));
    }

private:
    int width_, height_;
    CameraFrame frame_;
};

// What counting found so far.
struct Tally {
    uint64_t cells = 0;
    uint64_t tests = 0;
};

bool intersectTriangle(const Triangle &tri, const Ray &ray, const reference::WatertightRay &wray,
                       double tMax, double &t) {
    glm::dvec2 b12;
    return reference::intersectTriangle(ray, wray, glm::dvec3(tri.p[0]), glm::dvec3(tri.p[1]),
                                        glm::dvec3(tri.p[2]), tMax, t, b12);
}

// An instance's nearest hit closer than tMax: the ray in its prototype's space (where t is the
// same: the placement is a similarity) through the prototype's grid, as the tracer walks it:
// only the cells that the part of the ray in the scene grid's cell (tCellEnter to tCellExit)
// crosses (traverse.glsl, testInstance). The direction there is not unit length; the
// watertight test does not need it to be.
bool intersectInstance(const Scene &scene, const Grid &grid, const Instance &instance,
                       const Ray &ray, double tCellEnter, double tCellExit, double tMax, double &t,
                       Tally &tally) {
    const MeshPrototype &prototype = scene.prototypes[instance.prototype];
    const Grid &meshGrid = grid.meshGrids[instance.prototype];
    glm::dmat3 toObject = glm::transpose(instance.rotation) / instance.scale;
    Ray local{toObject * (ray.origin - instance.translation), toObject * ray.dir};
    reference::WatertightRay wray = reference::makeWatertightRay(local.dir);
    double nearest = tMax;
    walkGrid(meshGrid, local.origin, local.dir, tMax, [&](uint32_t cell, double, double tExit) {
        if (tExit < tCellEnter)
            return true; // before the scene cell: the tracer starts past it
        ++tally.cells;
        for (uint32_t k = meshGrid.cellStart[cell]; k < meshGrid.cellStart[cell + 1]; ++k) {
            ++tally.tests;
            double tHit;
            if (intersectTriangle(prototype.triangles[meshGrid.cellPrimitives[k]], local, wray,
                                  nearest, tHit))
                nearest = tHit;
        }
        return nearest > tExit && tExit < tCellExit;
    });
    t = nearest;
    return nearest < tMax;
}

// The nearest hit of primitive `id` closer than tMax, with the reference's exact tests.
bool intersectId(const Scene &scene, const Grid &grid, const PrimitiveIds &ids, uint32_t id,
                 const Ray &ray, const reference::WatertightRay &wray, double tCellEnter,
                 double tCellExit, double tMax, double &t, Tally &tally) {
    PrimitiveIds::Decoded d = ids.decode(id);
    if (d.kind == gpu::kKindSphere) {
        const Sphere &s = scene.spheres[d.index];
        return reference::intersectSphere(ray, glm::dvec3(s.center), double(s.radius), tMax, t);
    }
    if (d.kind == gpu::kKindTriangle)
        return intersectTriangle(scene.triangles[d.index], ray, wray, tMax, t);
    if (d.kind == gpu::kKindInstance)
        return intersectInstance(scene, grid, scene.instances[d.index], ray, tCellEnter, tCellExit,
                                 tMax, t, tally);
    // A new finite kind needs its test here (docs/design.md, "Adding a primitive").
    throw Error("countWalks has no test for primitive kind " + std::to_string(d.kind));
}

} // namespace

WalkCounts countWalks(const Scene &scene, const Grid &grid, double aspect, int columns,
                      double stopAboveTestsPerRay) {
    return countWalks(scene, scene.camera, grid, aspect, columns, stopAboveTestsPerRay);
}

WalkCounts countWalks(const Scene &scene, const Camera &camera, const Grid &grid, double aspect,
                      int columns, double stopAboveTestsPerRay) {
    PrimitiveIds ids(scene);
    RayLattice lattice(camera, aspect, columns);
    WalkCounts counts;
    Tally tally;
    double rays = double(lattice.count());
    double stopAbove = stopAboveTestsPerRay * rays;
    for (size_t i = 0; i < lattice.count() && !counts.stopped; ++i) {
        Ray ray = lattice.ray(i);
        reference::WatertightRay wray = reference::makeWatertightRay(ray.dir);
        double nearest = std::numeric_limits<double>::infinity();
        walkGrid(grid, ray.origin, ray.dir, nearest,
                 [&](uint32_t cell, double tEnter, double tExit) {
                     ++tally.cells;
                     for (uint32_t k = grid.cellStart[cell]; k < grid.cellStart[cell + 1]; ++k) {
                         ++tally.tests;
                         double t;
                         if (intersectId(scene, grid, ids, grid.cellPrimitives[k], ray, wray,
                                         tEnter, tExit, nearest, t, tally))
                             nearest = t;
                     }
                     return nearest > tExit; // on until the nearest hit is in a cell reached
                 });
        ++counts.rays;
        counts.nearestHits.push_back(nearest);
        counts.stopped = double(tally.tests) > stopAbove;
    }
    // Per ray of the whole lattice: where counting stopped, the rays not walked count zero.
    counts.cellsPerRay = double(tally.cells) / rays;
    counts.testsPerRay = double(tally.tests) / rays;
    return counts;
}

WalkCounts lowerBoundWalks(const Scene &scene, const Grid &layout, double aspect, int columns,
                           const std::vector<double> &nearestHits) {
    RayLattice lattice(scene.camera, aspect, columns);
    if (nearestHits.size() != lattice.count())
        throw Error("lowerBoundWalks: " + std::to_string(nearestHits.size()) + " hits for " +
                    std::to_string(lattice.count()) + " rays");
    WalkCounts counts;
    uint64_t cells = 0, hits = 0;
    for (size_t i = 0; i < lattice.count(); ++i) {
        Ray ray = lattice.ray(i);
        double nearest = nearestHits[i];
        uint64_t crossed = 0;
        walkGrid(layout, ray.origin, ray.dir, std::numeric_limits<double>::infinity(),
                 [&](uint32_t, double, double tExit) {
                     ++crossed;
                     return tExit < nearest;
                 });
        cells += crossed > 0 ? crossed - 1 : 0;
        hits += nearest < std::numeric_limits<double>::infinity() ? 1 : 0;
        ++counts.rays;
    }
    double rays = double(lattice.count());
    counts.cellsPerRay = double(cells) / rays;
    counts.testsPerRay = double(hits) / rays;
    counts.stopped = true;
    return counts;
}

} // namespace prism
