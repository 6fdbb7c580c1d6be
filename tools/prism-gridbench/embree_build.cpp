#include "embree_build.h"

#include <string>

#include <embree3/rtcore.h>

#include "core/error.h"
#include "core/timer.h"

namespace prism {
namespace {

// One owner for each Embree handle.
struct Device {
    RTCDevice handle = rtcNewDevice(nullptr);
    ~Device() { rtcReleaseDevice(handle); }
};
struct SceneHandle {
    RTCScene handle;
    explicit SceneHandle(RTCDevice device) : handle(rtcNewScene(device)) {}
    ~SceneHandle() { rtcReleaseScene(handle); }
};

void check(RTCDevice device, const char *what) {
    RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw Error(std::string("Embree: ") + what + " failed (error " + std::to_string(error) +
                    ")");
}

void addTriangles(RTCDevice device, RTCScene scene, const std::vector<Triangle> &triangles) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto *vertices = static_cast<float *>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), 3 * triangles.size()));
    auto *indices = static_cast<unsigned *>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), triangles.size()));
    check(device, "allocating triangle buffers");
    for (size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            for (int a = 0; a < 3; ++a)
                vertices[9 * t + 3 * k + a] = triangles[t].p[k][a];
            indices[3 * t + k] = unsigned(3 * t + k);
        }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
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
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
}

} // namespace

bool embreeAvailable() {
    return true;
}

EmbreeBuild timeEmbreeBuild(const Scene &scene) {
    EmbreeBuild result;
    Timer setup;
    Device device;
    check(device.handle, "rtcNewDevice");
    SceneHandle bvh(device.handle);
    if (!scene.triangles.empty())
        addTriangles(device.handle, bvh.handle, scene.triangles);
    if (!scene.spheres.empty())
        addSpheres(device.handle, bvh.handle, scene.spheres);
    result.setupMs = setup.elapsedMs();
    Timer commit;
    rtcCommitScene(bvh.handle);
    result.commitMs = commit.elapsedMs();
    check(device.handle, "rtcCommitScene");
    return result;
}

} // namespace prism
