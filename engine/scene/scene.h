#pragma once
// The scene model every part of Prism shares: what a .scene file (and the OBJ files it names)
// describes, after parsing, defaults and mesh transforms. No Vulkan here.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh_transform.h"

namespace prism {

// Positions are double on the host so that a scene far from its file's origin loses nothing
// before it is centred on the camera (scene/scene_origin.h); directions and colours are float.
struct Camera {
    glm::dvec3 eye{0.0, 0.0, 5.0};
    glm::dvec3 look{0.0, 0.0, 0.0};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovDegrees = 60.0f; // vertical field of view (perspective only)
    float orthoHeight = 0.0f; // > 0: parallel projection with an image plane this tall
    bool isOrtho() const { return orthoHeight > 0.0f; }
};

struct Light {
    glm::dvec3 position{0.0};
    glm::vec3 color{1.0f};
    float radius = 0.0f; // > 0: spherical area light (soft shadows)
};

// RGBA texels, row 0 = the image's top row (as stored on disk): linear radiance for colour
// textures, the stored values scaled to [0, 1] for data (normal and bump maps).
struct Texture {
    std::string path;
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> texels; // width * height; colour already decoded from sRGB where 8-bit
};

constexpr int32_t kNoTexture = -1;

struct Material {
    std::string name;
    glm::vec3 color{0.8f};
    float ambient = 0.1f;
    float diffuse = 0.9f;
    float specular = 0.0f;
    float shininess = 32.0f;
    float reflect = 0.0f;
    float transmit = 0.0f;
    float ior = 1.5f;
    int32_t texture = kNoTexture; // index into Scene::textures
    // Shading-normal maps (docs/scene-format.md, "Normal and bump maps"), indices into
    // Scene::textures of images read as data, not colour: a tangent-space normal map, and a
    // height map whose slope, times bumpScale, tilts the normal (Blinn 1978).
    int32_t normalMap = kNoTexture;
    int32_t bumpMap = kNoTexture;
    float bumpScale = 1.0f; // MTL -bm; heights in texture-coordinate units
    bool hasSurfaceMaps() const { return normalMap != kNoTexture || bumpMap != kNoTexture; }
};

// What rays that miss everything see instead of the background: a lat-long image
// (docs/scene-format.md, `environment`). It does not light the scene (Whitted: lights do).
struct Environment {
    int32_t texture = kNoTexture; // index into Scene::textures
    float intensity = 1.0f;
    float rotateDegrees = 0.0f; // about +y
};

struct Sphere {
    glm::dvec3 center{0.0};
    float radius = 1.0f;
    uint32_t material = 0;
};

struct Plane {
    glm::dvec3 point{0.0};
    glm::vec3 normal{0.0f, 1.0f, 0.0f}; // unit length (normalised by the parser)
    uint32_t material = 0;
};

// A triangle's vertex normals and texture coordinates. Kept beside the triangles, in a list of
// their owner's that a triangle points into, rather than in every triangle: most big meshes have
// neither, and a triangle with them inline took 144 bytes where its positions need 72 (issue 31).
struct TriangleShading {
    glm::vec3 n[3]{};  // vertex normals, valid when hasNormals
    glm::vec2 uv[3]{}; // texture coordinates, valid when hasUVs
    bool hasNormals = false;
    bool hasUVs = false;
};

constexpr uint32_t kNoShading = ~0u;

struct Triangle {
    glm::dvec3 p[3]; // counter-clockwise front face; Ng = (p1 - p0) x (p2 - p0)
    uint32_t material = 0;
    uint32_t shading = kNoShading; // index into its owner's shading list; none: flat, no UVs
};
static_assert(sizeof(Triangle) == 80);

// The record `t` points to in `shading` (its owner's list), or an empty one (no normals, no
// texture coordinates) for a triangle without.
inline const TriangleShading &shadingOf(const Triangle &t,
                                        std::span<const TriangleShading> shading) {
    static const TriangleShading none;
    return t.shading == kNoShading ? none : shading[t.shading];
}

// The record `t` points to in `shading`, made (empty) if it has none yet.
inline TriangleShading &shadingFor(Triangle &t, std::vector<TriangleShading> &shading) {
    if (t.shading == kNoShading) {
        t.shading = uint32_t(shading.size());
        shading.emplace_back();
    }
    return shading[t.shading];
}

// Appends the triangles `from` (whose records are in `fromShading`) to `to`, their records to
// `toShading`, the appended triangles pointing to them there.
void appendTriangles(std::vector<Triangle> &to, std::vector<TriangleShading> &toShading,
                     std::span<const Triangle> from, std::span<const TriangleShading> fromShading);

// A mesh loaded once by `mesh PATH ... as NAME` and drawn by `place NAME` lines
// (docs/scene-format.md, "Instances"): its triangles in its own space, which the loader centres
// on their bounding box so that an instance's coordinates stay as small as the mesh is.
struct MeshPrototype {
    std::string name;
    std::vector<Triangle> triangles;
    std::vector<TriangleShading> shading; // the records its triangles point to

    // Triangle i's normals and texture coordinates (an empty record where it has none).
    const TriangleShading &shadingOf(size_t i) const {
        return prism::shadingOf(triangles[i], shading);
    }
};

constexpr int32_t kOwnMaterials = -1; // an instance keeps its mesh's materials

// One placement of a prototype: p_world = translation + scale * rotation * p. A similarity (the
// scale is uniform, as on `mesh` lines), so t along a ray is the same in both spaces, and normals
// only turn.
struct Instance {
    uint32_t prototype = 0;
    double scale = 1.0;
    glm::dmat3 rotation{1.0};
    glm::dvec3 translation{0.0};
    int32_t material = kOwnMaterials; // otherwise every face of this placement uses it
    glm::dvec3 toWorld(const glm::dvec3 &p) const { return translation + scale * (rotation * p); }
    bool operator==(const Instance &) const = default;
};

// Keyed placements (format 1.2, docs/scene-format.md, "Animation"): `key` lines under a `place`
// line move its instance. Every key holds the whole placement as its line and the keys above it
// give it: in the file's coordinates, the prototype's centre not yet taken in (Scene::origin is
// taken off at each frame), a key's rotations about the place line's axes in its order.
struct PlacementKey {
    double frame = 1.0;
    MeshTransform transform;
    int line = 0; // the `key` line (keys[0]: the `place` line, frame 1)
};

struct PlacementTrack {
    uint32_t instance = 0;               // into Scene::instances
    Instance first;                      // at frame 1 (moved and rounded as Scene::instances)
    glm::dvec3 centre{0.0};              // the prototype's, as `place` takes it in
    glm::dvec3 boxMin{0.0}, boxMax{0.0}; // the prototype's box, centred
    std::vector<PlacementKey> keys;      // keys[0] is the place line; at least one more
};

// Camera animation (format 1.2, docs/scene-format.md, "Animation"). The `camera` line is the
// camera at frame 1; each `key` line under it gives the camera at a later frame, changing only
// the fields it names. Frames are numbers (a renderer's frame numbers, or any real in between).
struct CameraKey {
    double frame = 1.0;
    Camera camera;
    int line = 0; // the `key` line (0: the camera line's own key at frame 1)
};

enum class KeyInterpolation { Linear, CatmullRom };

// `turntable FRAMES`: the camera orbits `center` about `axis` by `degrees` every `frames` frames,
// frame 1 being the camera line itself.
struct Turntable {
    double frames = 1.0;
    glm::dvec3 center{0.0};
    glm::dvec3 axis{0.0, 1.0, 0.0}; // unit length
    double degrees = 360.0;
    int line = 0;
};

struct CameraAnimation {
    std::vector<CameraKey> keys; // after frame 1, frames increasing; empty without `key` lines
    std::optional<Turntable> turntable;
    bool animated() const { return !keys.empty() || turntable.has_value(); }
};

struct Scene {
    // Where this scene's coordinate origin lies in its file's coordinates: 0 as loaded, the
    // camera's eye once centred for rendering (scene/scene_origin.h).
    glm::dvec3 origin{0.0};
    Camera camera; // at frame 1 (cameraAt in scene/camera_animation.h gives any frame's)
    CameraAnimation cameraAnimation;
    // Instances that move (scene/placement_animation.h gives their placements at any frame);
    // Scene::instances holds every instance at frame 1.
    std::vector<PlacementTrack> placementTracks;
    KeyInterpolation keyInterpolation = KeyInterpolation::Linear; // every key's, by `interpolate`
    glm::vec3 background{0.0f};
    Environment environment;
    glm::vec3 ambient{1.0f};
    std::vector<Light> lights;
    std::vector<Material> materials; // materials[0] is the built-in "default"
    std::vector<Texture> textures;
    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    std::vector<Triangle> triangles;              // in scene space
    std::vector<TriangleShading> triangleShading; // the records Scene::triangles point to
    std::vector<MeshPrototype> prototypes;        // drawn only where instances place them
    std::vector<Instance> instances;
    std::vector<std::string> warnings; // "FILE:LINE: warning: ..." lines, in order

    // Triangle i's normals and texture coordinates (an empty record where it has none).
    const TriangleShading &shadingOf(size_t i) const {
        return prism::shadingOf(triangles[i], triangleShading);
    }

    // Primitives that live in the grid (their ids: scene/primitive_ids.h); an instance is one,
    // its prototype's triangles live in a grid of their own.
    size_t finitePrimitiveCount() const {
        return spheres.size() + triangles.size() + instances.size();
    }
    // Triangles the prototypes store (once each, however often they are placed).
    size_t prototypeTriangleCount() const {
        size_t count = 0;
        for (const MeshPrototype &m : prototypes)
            count += m.triangles.size();
        return count;
    }
};

} // namespace prism
