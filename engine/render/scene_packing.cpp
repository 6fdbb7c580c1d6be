#include "render/scene_packing.h"

#include "core/error.h"
#include "scene/primitive_ids.h"

namespace prism {
namespace {

// Material indices travel in float lanes (gpu::indexFromFloat); floats hold integers exactly
// below 2^24.
float indexAsFloat(uint32_t index) {
    if (index >= (1u << 24))
        throw Error("scene has more than 16,777,216 materials");
    return static_cast<float>(index);
}

} // namespace

PackedScene packScene(const Scene &scene, const Grid &grid) {
    PackedScene packed;
    gpu::GpuSceneHeader &h = packed.header;
    h.gridMin = glm::vec4(grid.boundsMin, 0.0f);
    h.gridMax = glm::vec4(grid.boundsMax, 0.0f);
    h.cellSize = glm::vec4(grid.cellSize, 0.0f);
    glm::uvec3 res(grid.resolution);
    h.gridRes = glm::uvec4(res, res.x * res.y * res.z);
    h.counts = glm::uvec4(scene.spheres.size(), scene.planes.size(), scene.triangles.size(),
                          scene.lights.size());
    h.idEnd = PrimitiveIds(scene).end;
    h.background = glm::vec4(scene.background, 1.0f);
    h.ambient = glm::vec4(scene.ambient, 1.0f);
    const Environment &e = scene.environment;
    h.environment = glm::vec4(float(e.texture), e.intensity, glm::radians(e.rotateDegrees), 0.0f);

    for (const Sphere &s : scene.spheres)
        packed.spheres.push_back(
            {glm::vec4(s.center, s.radius), glm::vec4(indexAsFloat(s.material), 0.0f, 0.0f, 0.0f)});
    for (const Plane &p : scene.planes)
        packed.planes.push_back(
            {glm::vec4(p.normal, float(glm::dot(glm::dvec3(p.normal), p.point))),
             glm::vec4(glm::vec3(p.point), indexAsFloat(p.material))});

    // The tracer reads shading data for every triangle hit where the scene has vertex normals,
    // textures or normal/bump maps (tracer_features.h): then every triangle has its record.
    bool needShading = false;
    for (const Triangle &t : scene.triangles)
        needShading = needShading || t.hasNormals || t.hasUVs;
    for (const Material &m : scene.materials)
        needShading = needShading ||
                      ((m.texture != kNoTexture || m.hasSurfaceMaps()) && !scene.triangles.empty());
    for (const Triangle &t : scene.triangles) {
        packed.triangles.push_back({glm::vec4(t.p[0], indexAsFloat(t.material)),
                                    glm::vec4(t.p[1], 0.0f), glm::vec4(t.p[2], 0.0f)});
        if (needShading)
            packed.triangleShading.push_back({glm::vec4(t.n[0], t.hasNormals ? 1.0f : 0.0f),
                                              glm::vec4(t.n[1], t.hasUVs ? 1.0f : 0.0f),
                                              glm::vec4(t.n[2], 0.0f), glm::vec4(t.uv[0], t.uv[1]),
                                              glm::vec4(t.uv[2], 0.0f, 0.0f)});
    }

    for (const Material &m : scene.materials)
        packed.materials.push_back(
            {glm::vec4(m.color, m.ambient),
             glm::vec4(m.diffuse, m.specular, m.shininess, m.reflect),
             glm::vec4(m.transmit, m.ior, static_cast<float>(m.texture), 0.0f),
             glm::vec4(static_cast<float>(m.normalMap), static_cast<float>(m.bumpMap), m.bumpScale,
                       0.0f)});
    for (const Light &l : scene.lights)
        packed.lights.push_back({glm::vec4(l.position, l.radius), glm::vec4(l.color, 1.0f)});

    for (const Texture &t : scene.textures) {
        packed.textures.push_back({glm::uvec4(packed.texels.size(), t.width, t.height, 0)});
        packed.texels.insert(packed.texels.end(), t.texels.begin(), t.texels.end());
    }

    packed.cellStart = grid.cellStart;
    packed.cellPrimitives = grid.cellPrimitives;
    packed.gridEntries = grid.entries;
    packed.cellBoxes = grid.cellBoxes;
    for (size_t c = 0; c < packed.cellBoxes.size(); ++c)
        packed.cellBoxes[c].w = grid.cellStart[c]; // gpu::cellBoxFirstPrimitive
    h.voxelSize = glm::vec4(grid.voxelSize(), 0.0f);
    h.voxels = glm::uvec4(glm::uvec3(grid.voxelResolution()), grid.shift);
    return packed;
}

} // namespace prism
