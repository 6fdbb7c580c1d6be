#pragma once
// Merging the empty cells of a lattice into few boxes (the merge of Pérard-Gayot, Kalojanov &
// Slusallek 2017, for its commonest case): from each empty cell not yet taken, in x-fastest
// order, a box grows along x, then y, then z over empty cells not yet taken. The adaptive grid
// merges so the empty parts of each split and its empty top cells: a surface leaves most of
// them empty, and one cell each made most of the grid's cells, memory, expansion work and the
// walk's steps through empty space.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace prism {

// Calls box(lo, hi) for boxes [lo, hi) of the lattice of `size` cells, numbered x fastest,
// that cover every cell i where empty(i) holds, each in exactly one box, and no other.
// `taken` is the merge's marks, the caller's to reuse: a build merges the parts of every split
// it makes (at a million triangles, hundreds of thousands of small lattices), and an
// allocation for each was a fifth of the merge's time.
template <typename Empty, typename Box>
void mergeEmptyBoxes(glm::ivec3 size, Empty empty, Box box, std::vector<uint8_t> &taken) {
    auto index = [&](glm::ivec3 c) { return uint32_t(c.x + size.x * (c.y + size.y * c.z)); };
    taken.assign(size_t(size.x) * size_t(size.y) * size_t(size.z), 0);
    auto untaken = [&](glm::ivec3 c) { return empty(index(c)) && !taken[index(c)]; };
    auto untakenBox = [&](glm::ivec3 lo, glm::ivec3 hi) {
        for (int z = lo.z; z < hi.z; ++z)
            for (int y = lo.y; y < hi.y; ++y)
                for (int x = lo.x; x < hi.x; ++x)
                    if (!untaken({x, y, z}))
                        return false;
        return true;
    };
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                glm::ivec3 lo(x, y, z), hi = lo + 1;
                if (!untaken(lo))
                    continue;
                for (int axis = 0; axis < 3; ++axis)
                    for (;;) {
                        glm::ivec3 layerLo = lo, layerHi = hi;
                        layerLo[axis] = hi[axis];
                        layerHi[axis] = hi[axis] + 1;
                        if (hi[axis] >= size[axis] || !untakenBox(layerLo, layerHi))
                            break;
                        ++hi[axis];
                    }
                for (int cz = lo.z; cz < hi.z; ++cz)
                    for (int cy = lo.y; cy < hi.y; ++cy)
                        for (int cx = lo.x; cx < hi.x; ++cx)
                            taken[index({cx, cy, cz})] = true;
                box(lo, hi);
            }
}

} // namespace prism
