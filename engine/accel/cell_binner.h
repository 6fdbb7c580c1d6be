#pragma once
// Putting primitives into the cells of a lattice they overlap, exactly (each kind's own overlap
// test) and with a thin slack so that the shader's float walk never misses one.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "accel/bounds.h"
#include "accel/finite_primitives.h"
#include "accel/grid.h"

namespace prism {

// Cells of size cellSize from origin; binning looks at the window [lo, hi) of them, whose cells
// are numbered x fastest from 0.
struct Lattice {
    glm::dvec3 origin{0.0};
    glm::dvec3 cellSize{1.0};
    glm::ivec3 lo{0}, hi{1};
    double magnitude = 0.0; // largest |coordinate| of the whole grid: the scale of float error

    glm::ivec3 size() const { return hi - lo; }
    uint32_t count() const { return uint32_t(size().x * size().y * size().z); }
    uint32_t local(glm::ivec3 cell) const {
        glm::ivec3 c = cell - lo, s = size();
        return uint32_t(c.x + s.x * (c.y + s.y * c.z));
    }
};

// The whole grid's cells (the top cells of an adaptive grid).
Lattice wholeGrid(const Grid &grid);

class CellBinner {
public:
    explicit CellBinner(const Lattice &lattice) : lattice_(lattice) {
        // Cells are widened a little so a hit found by the shader's float walk near a cell face
        // is listed in the cell on either side of it (rounding may put the walk in either).
        slack_ = 1e-4 * lattice.cellSize + glm::dvec3(4e-7 * lattice.magnitude);
        inverseCellSize_ = 1.0 / lattice.cellSize;
    }

    // Appends (local cell, id) for every cell of the window that primitive `id` overlaps.
    void bin(uint32_t id, const FinitePrimitives &primitives,
             std::vector<std::pair<uint32_t, uint32_t>> &pairs) const {
        glm::ivec3 lo, hi;
        boundsRange(primitives.bounds(id), lo, hi);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                    if (overlaps(id, primitives, {x, y, z}))
                        pairs.emplace_back(lattice_.local({x, y, z}), id);
    }

    // The cells [lo, hi] (inclusive) of the window that `bounds`, grown by the slack, overlaps:
    // every cell a primitive with those bounds overlaps, and perhaps some more.
    void boundsRange(const Aabb &bounds, glm::ivec3 &lo, glm::ivec3 &hi) const {
        lo = cellOf(bounds.min - slack_);
        hi = cellOf(bounds.max + slack_);
    }

    // Primitive `id` against one cell (grown by the slack), exactly.
    bool overlaps(uint32_t id, const FinitePrimitives &primitives, glm::ivec3 cell) const {
        glm::dvec3 cmin = lattice_.origin + glm::dvec3(cell) * lattice_.cellSize;
        glm::dvec3 cmax = cmin + lattice_.cellSize;
        return primitives.overlapsBox(id, cmin - slack_, cmax + slack_);
    }

private:
    glm::ivec3 cellOf(const glm::dvec3 &p) const {
        glm::dvec3 f;
        for (int a = 0; a < 3; ++a)
            f[a] = floorOfQuotient(p[a] - lattice_.origin[a], a);
        return glm::clamp(glm::ivec3(glm::clamp(f, glm::dvec3(-1e9), glm::dvec3(1e9))), lattice_.lo,
                          lattice_.hi - 1);
    }

    // floor(d / cellSize[axis]), bit for bit, mostly without dividing: the product with the
    // reciprocal is within a few ulps of the quotient, so the two floor alike unless the
    // product lies that close to an integer; there the division decides.
    double floorOfQuotient(double d, int axis) const {
        double q = d * inverseCellSize_[axis], f = std::floor(q);
        double margin = 1e-12 * std::max(1.0, std::abs(q));
        if (q - f > margin && f + 1.0 - q > margin)
            return f;
        return std::floor(d / lattice_.cellSize[axis]);
    }

    Lattice lattice_;
    glm::dvec3 slack_;
    glm::dvec3 inverseCellSize_;
};

} // namespace prism
