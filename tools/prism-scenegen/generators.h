#pragma once
// The scene generators behind prism-scenegen's subcommands. Each returns the whole file text;
// `command` is the canonical command line written into the file's header.
#include <cstdint>
#include <string>

namespace prism::scenegen {

// The original's "randN" scenes: N spheres of random position, radius, colour and material
// inside a box standing on a floor, against two walls.
struct RandomOptions {
    uint32_t count = 50;
    uint64_t seed = 1;
    double box = 10.0; // side of the cube the spheres stay inside
    double minRadius = 0.4;
    double maxRadius = 0.8;
    uint32_t materials = 16; // size of the random palette the spheres draw from
};
std::string randomScene(const RandomOptions &options, const std::string &command);
std::string randomCommand(const RandomOptions &options);

// The original's "grid" scene: a regular n x n x n lattice of spheres above a floor.
struct LatticeOptions {
    uint32_t size = 10;   // spheres per side
    double spacing = 1.0; // between neighbouring centres
    double radius = 0.35;
};
std::string latticeScene(const LatticeOptions &options, const std::string &command);
std::string latticeCommand(const LatticeOptions &options);

// A row of `count` standing tori, about `triangles` triangles in all, on a floor: the
// same picture at any tessellation (per-ray cost against triangle count). `shards` long, thin
// triangles run through the whole row on the slant: a few huge triangles among many tiny ones,
// each crossing every cell along its path (the grids' hard case, issue 8).
struct ToriOptions {
    uint32_t triangles = 100000;
    uint32_t count = 5;
    uint32_t shards = 0;
};
std::string toriScene(const ToriOptions &options, const std::string &command);
std::string toriCommand(const ToriOptions &options);

// One closed mesh, a sphere of about `triangles` triangles (a subdivided cube pushed onto the
// sphere), over a floor: the dense single surface of the first-image ladder (issue 31). The
// mesh is an OBJ file (sphereMeshObj) that the scene names as `objName`, beside it.
struct SphereMeshOptions {
    uint32_t triangles = 100000;
    bool smooth = false; // `smooth` on the mesh line (vertex normals made at load)
};
std::string sphereMeshScene(const SphereMeshOptions &options, const std::string &objName,
                            const std::string &command);
std::string sphereMeshObj(const SphereMeshOptions &options, const std::string &command);
std::string sphereMeshCommand(const SphereMeshOptions &options);

// The original's "scene" (planes, triangles and spheres: 621 primitives) and "objects"
// (various triangle objects: 5436 triangles) benchmarks, laid out by hand in code.
std::string mixedScene(const std::string &command);
// `bunnyPath` is written as is into the `mesh` line (relative to the scene file).
std::string objectsScene(const std::string &bunnyPath, const std::string &command);

} // namespace prism::scenegen
