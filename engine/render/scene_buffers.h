#pragma once
// The packed scene on the GPU: one buffer per array, named, with a texel view on the arrays the
// tracer may read as texels, and their binding to the tracer's descriptors by the names of
// shaders/shared/trace_interface.h.
#include <cstdint>
#include <vector>

#include "render/scene_packing.h"
#include "vk/buffer.h"
#include "vk/buffer_view.h"
#include "vk/commands.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"

namespace prism {

// One scene array: its device-local buffer and, where the tracer can read it through a uniform
// texel buffer, that view.
struct SceneArray {
    vk::Buffer buffer;
    vk::BufferView texels;
};

// What one binding may hold on this device.
struct ArrayLimits {
    uint64_t storageBytes = 0;  // maxStorageBufferRange, or a lower limit a test sets
    uint64_t texelElements = 0; // maxTexelBufferElements
    bool texelReads = true;     // arrays are read through their texel views
};

struct SceneBuffers {
    vk::Buffer header;
    SceneArray spheres;
    SceneArray planes;
    SceneArray triangles;
    SceneArray triangleShading;
    SceneArray materials;
    SceneArray lights;
    SceneArray cellStart;
    SceneArray cellPrimitives;
    SceneArray cellTriangles;
    SceneArray cellSpheres;
    SceneArray textures;
    SceneArray texels;
    SceneArray gridEntries;
    SceneArray cellBoxes;
    SceneArray instances;
    SceneArray meshGrids;
};

// How arrays reach device-local memory: written in place where the device shares the host's
// memory (a CPU device: the arrays of a 1M-triangle scene, 390 MB, are then written once, not
// into a staging copy and copied again), else through a staging buffer. Staged everywhere is
// for the tests that compare the two.
enum class UploadPath { InPlaceWhereShared, Staged };

// Uploads every array. An array larger than the binding it is read through may hold is refused
// with a prism::Error naming the array, the device and the limit, never truncated.
SceneBuffers uploadScene(const vk::Context &context, vk::CommandRunner &runner,
                         const PackedScene &packed, const ArrayLimits &limits,
                         UploadPath path = UploadPath::InPlaceWhereShared);

// What one array takes on the device: its buffer's size (an empty array's is one 16-byte
// element), named as in errors ("triangle", "instance", ...).
struct ArrayBytes {
    const char *what;
    uint64_t bytes;
};
std::vector<ArrayBytes> arrayBytes(const SceneBuffers &buffers);

// Descriptor types of every binding of trace.comp, by binding number: the images, the storage
// buffers, and a uniform texel buffer for each array read as texels.
std::vector<VkDescriptorType> traceDescriptorTypes();

// Binds every array to its storage binding (capped at limits.storageBytes; an array past the cap
// has a texel view and is read only through it) and to its texel binding where it has one.
void bindScene(vk::ComputePipeline &pipeline, const SceneBuffers &buffers,
               const ArrayLimits &limits);

} // namespace prism
