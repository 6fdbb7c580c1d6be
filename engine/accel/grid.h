#pragma once
// A regular grid over the finite primitives (spheres, triangles) of a scene, stored compactly
// (CSR: per-cell offsets + one primitive-id array) for upload to the GPU. Infinite planes stay
// outside it. No Vulkan here.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism {

struct GridOptions {
    enum class Mode {
        // Regular or adaptive, whichever the tracer's counted work on the camera's rays says is
        // cheaper (accel/grid_choice.h).
        Auto,
        Regular, // cells ~ density * primitives, aspect following the bounds
        Off,     // one cell holding everything: every ray tests every primitive
        Fixed,   // resolution given by the user
        // A coarse top grid whose crowded cells are split again, level by level, each to its
        // own density (a power of two per axis): dense regions get small cells, sparse
        // regions large ones, so a small dense object in a large scene is not one cell.
        Adaptive,
        // The same top grid, each crowded top cell split once by density: the two-level grid
        // the adaptive one grew from, for comparison (accel/adaptive_grid.h, kTwoLevelStyle).
        TwoLevel,
    };
    Mode mode = Mode::Auto;
    glm::ivec3 resolution{1}; // Fixed only
    // Regular (and Auto's regular grid): target cells per primitive (lambda). Measured, see
    // docs/grid-density.md.
    float density = 4.0f;
    // How much the build does for the rays it will serve (docs/design.md, "Build effort by the
    // image"). Full: the adaptive grid's cells grown over their neighbours
    // (accel/cell_expansion.h), and each cell's triangles copied into its list for the tracer
    // (render/tracer_features.h): fewest steps and loads a ray. Lean: cells as built, lists of
    // primitive ids by bounding box (no exact tests): a quarter of the build and a third of a
    // big mesh's device memory, each ray 1.1-1.2x slower at 100k triangles, 1.6-1.7x at 1M with
    // exact lists and 5-11% more without. Auto: lean where the camera samples the grid will
    // serve (cameraSamples) are fewer than kLeanBelowSamplesPerPrimitive a primitive; 0 means
    // unknown, and many (a viewer, a Python session): full.
    enum class Effort { Auto, Full, Lean };
    Effort effort = Effort::Auto;
    uint64_t cameraSamples = 0;
};

// Camera samples a primitive under which --grid-build auto builds lean. On lavapipe the full
// build pays for itself at 12-13 samples a primitive with one shadow ray a sample (a 1M mesh,
// tori of 100k), at 4-5 where reflections and refractions make 6 rays a sample (the showcase);
// the lower figure is kept, so that no scene with many rays loses its trace speed.
constexpr double kLeanBelowSamplesPerPrimitive = 4.0;

// Whether a build with `options` over `finitePrimitives` grid primitives is lean.
bool buildsLean(const GridOptions &options, uint64_t finitePrimitives);

// Parses --grid-build's argument: auto, full or lean.
GridOptions::Effort parseGridBuild(std::string_view text);

// Parses --grid's argument: "auto", "regular", "off", "adaptive", "two-level", "N" (N^3) or
// "NxNyNz", each count in 1..1024.
// Throws prism::Error with a message naming the bad text.
GridOptions parseGridOption(std::string_view text);

// The adaptive grid's entries and cells are indexed by 28 bits: an entry keeps 4 bits for the
// split (and the tracer's cell records by their rows, render/scene_packing.h).
constexpr uint32_t kMaxAdaptiveIndex = 1u << 28;

// Either a regular grid or an adaptive one (entries not empty). The adaptive grid's cells have
// boxes on a virtual grid of voxels, 2^shift per top cell and axis; its voxel map (entries)
// finds the cell that holds a voxel, and a ray steps from the exit face of one cell's box to
// the cell behind it.
struct Grid {
    glm::vec3 boundsMin{0.0f};
    glm::vec3 boundsMax{1.0f};
    glm::ivec3 resolution{1}; // cells per axis; adaptive: top cells per axis
    glm::vec3 cellSize{1.0f}; // adaptive: the top cells' size
    // Regular: cell (x, y, z) has index x + res.x * (y + res.y * z). Both: a cell's primitives
    // are cellPrimitives[cellStart[i] .. cellStart[i + 1]), ids as in scene/primitive_ids.h.
    std::vector<uint32_t> cellStart;
    std::vector<uint32_t> cellPrimitives;

    // Adaptive only. The voxel map is a tree of entries whose first topCellCount() are the top
    // cells (indexed like regular cells). An entry with split d = entry & 15 > 0 divides its
    // box into 2^d parts per axis whose entries start at entry >> 4 (x fastest); an entry with
    // d = 0 is a leaf: cell entry >> 4. cellBoxes[c] is cell c's box in voxels (packCellBox).
    uint32_t shift = 0;
    std::vector<uint32_t> entries;
    std::vector<glm::uvec4> cellBoxes;
    uint32_t depth = 0; // the deepest leaf's level below the top (a lookup's iterations)
    // Built lean (GridOptions::effort): adaptive cells left as built, not expanded, and the
    // tracer reads the cells' primitive ids rather than copies of their triangles.
    bool lean = false;

    uint32_t maxPerCell = 0; // the fullest cell's count, for --stats and the benchmarks
    std::string choice;      // Auto only: which grid it chose, and the counts it chose by

    // One regular grid per Scene::prototypes entry, over its triangles in its own space (ids:
    // the prototype's triangle indices): the second level under the instances of this grid.
    std::vector<Grid> meshGrids;

    bool adaptive() const { return !entries.empty(); }
    // Cells holding primitive lists.
    uint64_t cellCount() const { return adaptive() ? cellBoxes.size() : topCellCount(); }
    uint64_t topCellCount() const {
        return uint64_t(resolution.x) * uint64_t(resolution.y) * uint64_t(resolution.z);
    }
    // Voxels per axis of the virtual grid (regular: cells per axis). A ray crosses at most
    // their sum of cells.
    glm::ivec3 voxelResolution() const { return resolution * (1 << shift); }
    glm::vec3 voxelSize() const { return cellSize / float(1u << shift); }
    // Bytes the grid takes on the GPU, the mesh grids' included.
    uint64_t bytes() const {
        uint64_t total =
            4 * (cellStart.size() + cellPrimitives.size() + entries.size()) + 16 * cellBoxes.size();
        for (const Grid &mesh : meshGrids)
            total += mesh.bytes();
        return total;
    }
    uint32_t cellIndex(glm::ivec3 cell) const {
        return uint32_t(cell.x + resolution.x * (cell.y + resolution.y * cell.z));
    }
};

Grid buildGrid(const Scene &scene, const GridOptions &options = {});

// buildGrid with the prototypes' mesh grids taken from `meshGrids` (a grid built before for the
// same prototypes: accel/grid_cache.h, meshGridsKey) instead of built again: only the level the
// spheres, triangles and instances are in is built (a viewer's reload that moved instances).
Grid buildGridOverMeshGrids(const Scene &scene, const GridOptions &options,
                            const std::vector<Grid> &meshGrids);

// The grid of `scene` whose instances have moved since `previous` was built for it (a keyed
// placement's next frame): the level the instances are in built again, the prototypes' mesh
// grids taken over from `previous` untouched. With --grid auto, `previous`'s kind is kept.
Grid rebuildInstanceLevel(const Scene &scene, Grid previous, const GridOptions &options);

// A cell box in voxels, as the tracer reads it: 16 bits per coordinate.
glm::uvec4 packCellBox(glm::ivec3 min, glm::ivec3 max);
void unpackCellBox(const glm::uvec4 &packed, glm::ivec3 &min, glm::ivec3 &max);

} // namespace prism
