#include "embree_baseline.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

#include "core/error.h"
#include "core/parallel_for.h"
#include "core/timer.h"
#include "reference/camera_model.h"
#include "scene/camera_frame.h"
#include "scene/instance_flattening.h"

namespace prism {
namespace {

constexpr int kPacket = 8; // rays per rtcIntersect8 / rtcOccluded8: 8 pixels of a row

void check(RTCDevice device, const char *what) {
    RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw Error(std::string("Embree: ") + what + " failed (error " + std::to_string(error) +
                    ")");
}

void attach(RTCScene scene, RTCGeometry geometry) {
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
}

// Triangles as three vertices each (Prism's triangles are unindexed).
void addTriangles(RTCDevice device, RTCScene scene, const std::vector<glm::vec3> &corners) {
    size_t count = corners.size() / 3;
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto *vertices = static_cast<float *>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * count));
    auto *indices = static_cast<unsigned *>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
    check(device, "allocating triangle buffers");
    for (size_t i = 0; i < corners.size(); ++i) {
        for (int a = 0; a < 3; ++a)
            vertices[3 * i + a] = corners[i][a];
        indices[i] = unsigned(i);
    }
    attach(scene, geometry);
}

void addSpheres(RTCDevice device, RTCScene scene, const std::vector<Sphere> &spheres) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto *points = static_cast<float *>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), spheres.size()));
    check(device, "allocating sphere buffers");
    for (size_t s = 0; s < spheres.size(); ++s) {
        for (int a = 0; a < 3; ++a)
            points[4 * s + a] = spheres[s].center[a];
        points[4 * s + 3] = spheres[s].radius;
    }
    attach(scene, geometry);
}

// Each plane as two triangles `reach` across around the point of it nearest the scene's centre.
std::vector<glm::vec3> planeQuads(const Scene &scene, const glm::vec3 &centre, float reach) {
    std::vector<glm::vec3> corners;
    for (const Plane &p : scene.planes) {
        glm::vec3 n = glm::normalize(p.normal);
        glm::vec3 o = centre - glm::dot(centre - glm::vec3(p.point), n) * n;
        glm::vec3 u = glm::normalize(
            glm::cross(n, std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
        glm::vec3 v = glm::cross(n, u);
        glm::vec3 a = o - reach * (u + v), b = o + reach * (u - v), c = o + reach * (u + v),
                  d = o - reach * (u - v);
        corners.insert(corners.end(), {a, b, c, a, c, d});
    }
    return corners;
}

} // namespace

struct EmbreeBaseline::State {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    EmbreeBuild build;
    const Scene *source = nullptr;
    CameraFrame frame{};
    ~State() {
        if (scene)
            rtcReleaseScene(scene);
        if (device)
            rtcReleaseDevice(device);
    }
};

bool embreeAvailable() {
    return true;
}

EmbreeBaseline::EmbreeBaseline(const Scene &scene, uint32_t width, uint32_t height)
    : state_(std::make_unique<State>()) {
    State &s = *state_;
    s.source = &scene;
    s.frame = makeCameraFrame(scene.camera, int(width), int(height));
    Timer setup;
    s.device = rtcNewDevice(nullptr);
    if (!s.device)
        throw Error("Embree: rtcNewDevice failed");
    s.scene = rtcNewScene(s.device);
    check(s.device, "rtcNewScene");
    std::vector<glm::vec3> corners;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    // Instances as plain triangles: the baseline is Embree's flat BVH over the same surfaces.
    std::vector<Triangle> triangles = scene.triangles;
    for (const Instance &instance : scene.instances) {
        std::vector<Triangle> placed = placedTriangles(scene, instance).triangles;
        triangles.insert(triangles.end(), placed.begin(), placed.end());
    }
    for (const Triangle &t : triangles)
        for (const glm::dvec3 &corner : t.p) {
            glm::vec3 p(corner); // the scene is centred on the camera: floats are fine here
            corners.push_back(p);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    for (const Sphere &sp : scene.spheres) {
        lo = glm::min(lo, glm::vec3(sp.center) - sp.radius);
        hi = glm::max(hi, glm::vec3(sp.center) + sp.radius);
    }
    if (!corners.empty())
        addTriangles(s.device, s.scene, corners);
    if (!scene.spheres.empty())
        addSpheres(s.device, s.scene, scene.spheres);
    glm::vec3 centre = lo.x <= hi.x ? 0.5f * (lo + hi) : glm::vec3(0.0f);
    float size = lo.x <= hi.x ? std::max(1.0f, glm::length(hi - lo)) : 1.0f;
    std::vector<glm::vec3> planes = planeQuads(scene, centre, 1e4f * size);
    if (!planes.empty())
        addTriangles(s.device, s.scene, planes);
    s.build.setupMs = setup.elapsedMs();
    Timer commit;
    rtcCommitScene(s.scene);
    s.build.commitMs = commit.elapsedMs();
    check(s.device, "rtcCommitScene");
}

EmbreeBaseline::~EmbreeBaseline() = default;

const EmbreeBuild &EmbreeBaseline::build() const {
    return state_->build;
}

EmbreeFrame EmbreeBaseline::traceFrame() {
    const State &s = *state_;
    const Scene &scene = *s.source;
    int width = s.frame.width, height = s.frame.height;
    std::atomic<uint64_t> shadowRays{0};
    Timer timer;
    parallelFor(size_t(height), [&](size_t y) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        uint64_t shadows = 0;
        for (int x0 = 0; x0 < width; x0 += kPacket) {
            alignas(32) RTCRayHit8 primary;
            alignas(32) int valid[kPacket];
            for (int i = 0; i < kPacket; ++i) {
                valid[i] = x0 + i < width ? -1 : 0;
                Ray ray = cameraRay(s.frame, glm::dvec2(x0 + i + 0.5, double(y) + 0.5));
                primary.ray.org_x[i] = float(ray.origin.x);
                primary.ray.org_y[i] = float(ray.origin.y);
                primary.ray.org_z[i] = float(ray.origin.z);
                primary.ray.dir_x[i] = float(ray.dir.x);
                primary.ray.dir_y[i] = float(ray.dir.y);
                primary.ray.dir_z[i] = float(ray.dir.z);
                primary.ray.tnear[i] = 0.0f;
                primary.ray.tfar[i] = std::numeric_limits<float>::infinity();
                primary.ray.time[i] = 0.0f;
                primary.ray.mask[i] = ~0u;
                primary.ray.flags[i] = 0;
                primary.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
            }
            rtcIntersect8(valid, s.scene, &context, &primary);
            for (const Light &light : scene.lights) {
                alignas(32) RTCRay8 shadow;
                alignas(32) int shadowValid[kPacket];
                for (int i = 0; i < kPacket; ++i) {
                    shadowValid[i] = 0;
                    if (!valid[i] || primary.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID)
                        continue;
                    glm::vec3 dir(primary.ray.dir_x[i], primary.ray.dir_y[i], primary.ray.dir_z[i]);
                    glm::vec3 p = glm::vec3(primary.ray.org_x[i], primary.ray.org_y[i],
                                            primary.ray.org_z[i]) +
                                  primary.ray.tfar[i] * dir;
                    glm::vec3 n = glm::normalize(
                        glm::vec3(primary.hit.Ng_x[i], primary.hit.Ng_y[i], primary.hit.Ng_z[i]));
                    if (glm::dot(n, dir) > 0.0f)
                        n = -n;
                    glm::vec3 lightAt(light.position);
                    glm::vec3 toLight = lightAt - p;
                    float distance = glm::length(toLight);
                    if (glm::dot(n, toLight) <= 0.0f || distance <= 0.0f)
                        continue; // the surface faces away: Prism traces no shadow ray either
                    // Off the surface by a step relative to |p|, as Prism's offsetOrigin.
                    glm::vec3 origin = p + n * (1e-4f * std::max(1.0f, glm::length(p)));
                    glm::vec3 d = glm::normalize(lightAt - origin);
                    shadow.org_x[i] = origin.x;
                    shadow.org_y[i] = origin.y;
                    shadow.org_z[i] = origin.z;
                    shadow.dir_x[i] = d.x;
                    shadow.dir_y[i] = d.y;
                    shadow.dir_z[i] = d.z;
                    shadow.tnear[i] = 0.0f;
                    shadow.tfar[i] = glm::length(lightAt - origin);
                    shadow.time[i] = 0.0f;
                    shadow.mask[i] = ~0u;
                    shadow.flags[i] = 0;
                    shadowValid[i] = -1;
                    ++shadows;
                }
                rtcOccluded8(shadowValid, s.scene, &context, &shadow);
            }
        }
        shadowRays += shadows;
    });
    EmbreeFrame f;
    f.ms = timer.elapsedMs();
    f.rays.primary = uint64_t(width) * uint64_t(height);
    f.rays.shadow = shadowRays;
    return f;
}

} // namespace prism
