// The kinds of primitive, named once for the host, the grid and the tracer. Finite kinds live in
// the grid and share one id space: kind k owns the ids [primitiveIdFirst(idEnd, k), idEnd[k]),
// kinds in the order below. A new finite kind is one more constant and one more range.
#ifndef PRISM_PRIMITIVE_KINDS_H
#define PRISM_PRIMITIVE_KINDS_H
#include "glsl_compat.h"

PRISM_NAMESPACE_BEGIN

PRISM_CONST(uint, kKindSphere, 0u);
PRISM_CONST(uint, kKindTriangle, 1u);
// A placement of a mesh prototype: the grid holds its box; its triangles are found by a walk of
// the prototype's own grid in its own space (traverse.glsl). A hit on it is a triangle hit.
PRISM_CONST(uint, kKindInstance, 2u);
PRISM_CONST(uint, kFiniteKindCount, 3u); // at most 4: the ends travel in one uvec4
PRISM_CONST(uint, kKindPlane, 3u);       // infinite: outside the grid, tested by brute force
PRISM_CONST(uint, kKindNone, 0xFFFFFFFFu);

// First grid id of finite kind `kind`, given each kind's end.
PRISM_INLINE uint primitiveIdFirst(PRISM_IN(uvec4) idEnd, uint kind) {
    return kind == 0u ? 0u : idEnd[kind - 1u];
}

PRISM_NAMESPACE_END

#endif
