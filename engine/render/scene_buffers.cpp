#include "render/scene_buffers.h"

#include <algorithm>
#include <cstring>
#include <span>

#include "core/error.h"
#include "core/huge_pages.h"
#include "shared/trace_interface.h"

namespace prism {
namespace {

// How an array is read as texels: its format and bytes per texel.
struct TexelLayout {
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint64_t bytes = 0;
};
constexpr TexelLayout kUintTexels{VK_FORMAT_R32_UINT, 4};
constexpr TexelLayout kVec4Texels{VK_FORMAT_R32G32B32A32_SFLOAT, 16};
constexpr TexelLayout kUvec4Texels{VK_FORMAT_R32G32B32A32_UINT, 16};

class Uploader {
public:
    Uploader(const vk::Context &context, vk::CommandRunner &runner, const ArrayLimits &limits,
             UploadPath path)
        : context_(context), runner_(runner), limits_(limits), path_(path) {}

    // An array of `bytes` that write(to) writes, read through storage and texel bindings.
    template <typename Write>
    SceneArray array(uint64_t bytes, Write write, const char *what, TexelLayout texels) {
        checkFits(bytes, what, texels);
        SceneArray array;
        array.buffer = upload(bytes, write, true);
        array.texels = vk::BufferView(
            context_, array.buffer.handle(), texels.format,
            std::min<uint64_t>(array.buffer.size(), limits_.texelElements * texels.bytes));
        return array;
    }

    vk::Buffer upload(const void *data, uint64_t bytes, bool texelView,
                      VkBufferUsageFlags kind = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {
        return upload(
            bytes, [&](std::byte *to) { std::memcpy(to, data, bytes); }, texelView, kind);
    }

    // A buffer whose first `bytes` write(to) writes, the rest zeros: where the device shares
    // the host's memory, straight into the buffer, else into a staging copy.
    template <typename Write>
    vk::Buffer upload(uint64_t bytes, Write write, bool texelView,
                      VkBufferUsageFlags kind = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {
        // Vulkan has no empty buffers; unused arrays get one 16-byte element nobody reads.
        VkDeviceSize size = bytes == 0 ? 16 : bytes;
        vk::Buffer target(context_, size,
                          kind | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                              (texelView ? VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT : 0),
                          false, path_ == UploadPath::InPlaceWhereShared);
        if (target.mapped()) { // coherent: the next submission sees the writes
            fill(target.mapped(), write, bytes, size);
            return target;
        }
        vk::Buffer staging(context_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
        fill(staging.mapped(), write, bytes, size);
        runner_.run([&](VkCommandBuffer commands) {
            VkBufferCopy region{0, 0, size};
            vkCmdCopyBuffer(commands, staging.handle(), target.handle(), 1, &region);
        });
        return target;
    }

private:
    // The array's bytes, then zeros to the buffer's end.
    template <typename Write>
    static void fill(void *to, Write &write, uint64_t bytes, VkDeviceSize size) {
        adviseHugePages(to, size); // lavapipe's memory is the host's: fault it in 2 MiB pages
        if (bytes)
            write(static_cast<std::byte *>(to));
        std::memset(static_cast<std::byte *>(to) + bytes, 0, size - bytes);
    }

    void checkFits(uint64_t bytes, const char *what, TexelLayout texels) const {
        std::string prefix = std::string("scene too large for ") + context_.deviceName() +
                             ": the " + what + " array ";
        if (limits_.texelReads) {
            uint64_t elements = bytes / texels.bytes;
            if (elements > limits_.texelElements)
                throw Error(prefix + "has " + std::to_string(elements) +
                            " texels but one texel buffer may hold at most " +
                            std::to_string(limits_.texelElements) + " (maxTexelBufferElements)");
        } else if (bytes > limits_.storageBytes) {
            throw Error(prefix + "needs " + std::to_string(bytes) +
                        " bytes but one storage buffer may hold at most " +
                        std::to_string(limits_.storageBytes) + " (maxStorageBufferRange)");
        }
    }

    const vk::Context &context_;
    vk::CommandRunner &runner_;
    const ArrayLimits &limits_;
    UploadPath path_;
};

// Where an array's bytes come from: their count, and a writer of them.
struct ArraySource {
    uint64_t (*bytes)(const PackedScene &);
    void (*write)(const PackedScene &, std::byte *to);
};

// An array of the packed scene, copied.
template <auto member> constexpr ArraySource fromPacked() {
    return {
        [](const PackedScene &p) { return uint64_t(std::as_bytes(std::span(p.*member)).size()); },
        [](const PackedScene &p, std::byte *to) {
            std::span<const std::byte> data = std::as_bytes(std::span(p.*member));
            std::memcpy(to, data.data(), data.size());
        }};
}

// The largest array is not held by the packed scene but written here (PackedScene).
constexpr ArraySource kCellTriangles{
    [](const PackedScene &p) { return cellTriangleRows(p) * sizeof(glm::uvec4); },
    [](const PackedScene &p, std::byte *to) {
        writeCellTriangles(
            p, std::span(reinterpret_cast<glm::uvec4 *>(to), size_t(cellTriangleRows(p))));
    }};

// The triangles and their shading records, written from the scene's triangles.
constexpr ArraySource kTriangles{
    [](const PackedScene &p) { return p.triangleCount * sizeof(gpu::GpuTriangle); },
    [](const PackedScene &p, std::byte *to) {
        writeTriangles(
            p, std::span(reinterpret_cast<gpu::GpuTriangle *>(to), size_t(p.triangleCount)));
    }};
constexpr ArraySource kTriangleShading{
    [](const PackedScene &p) {
        return p.triangleShading ? p.triangleCount * sizeof(gpu::GpuTriangleShading) : 0;
    },
    [](const PackedScene &p, std::byte *to) {
        if (p.triangleShading)
            writeTriangleShading(p, std::span(reinterpret_cast<gpu::GpuTriangleShading *>(to),
                                              size_t(p.triangleCount)));
    }};

// The cell boxes, each with its first primitive (writeCellBoxes), none where the cell records
// hold them.
constexpr ArraySource kCellBoxes{
    [](const PackedScene &p) {
        return p.cellRecords ? 0 : uint64_t(p.cellBoxes.size() * sizeof(glm::uvec4));
    },
    [](const PackedScene &p, std::byte *to) {
        if (!p.cellRecords)
            writeCellBoxes(p, std::span(reinterpret_cast<glm::uvec4 *>(to), p.cellBoxes.size()));
    }};

// An array of the packed scene, copied, but none of it where `unread` is set: the tracer then
// reads the same from elsewhere (the cell triangle array: PackedScene).
template <auto member, bool PackedScene::*unread> constexpr ArraySource fromPackedUnless() {
    return {[](const PackedScene &p) { return p.*unread ? 0 : fromPacked<member>().bytes(p); },
            [](const PackedScene &p, std::byte *to) {
                if (!(p.*unread))
                    fromPacked<member>().write(p, to);
            }};
}

// Every scene array once: where it comes from, its name in errors, its bindings
// (shared/trace_interface.h) and whether the tracer may read it as texels.
struct ArrayBinding {
    SceneArray SceneBuffers::*array;
    ArraySource source;
    const char *what;
    uint32_t storageBinding;
    uint32_t texelBinding;
    TexelLayout texels;
};

using namespace gpu;
using P = PackedScene;
using B = SceneBuffers;
const ArrayBinding kArrays[] = {
    {&B::spheres, fromPacked<&P::spheres>(), "sphere", kBindingSpheres, kBindingSphereTexels,
     kVec4Texels},
    {&B::planes, fromPacked<&P::planes>(), "plane", kBindingPlanes, kBindingPlaneTexels,
     kVec4Texels},
    {&B::triangles, kTriangles, "triangle", kBindingTriangles, kBindingTriangleTexels, kVec4Texels},
    {&B::triangleShading, kTriangleShading, "triangle shading", kBindingTriangleShading,
     kBindingTriangleShadingTexels, kVec4Texels},
    {&B::materials, fromPacked<&P::materials>(), "material", kBindingMaterials,
     kBindingMaterialTexels, kVec4Texels},
    {&B::lights, fromPacked<&P::lights>(), "light", kBindingLights, kBindingLightTexels,
     kVec4Texels},
    {&B::cellStart, fromPackedUnless<&P::cellStart, &P::cellRecords>(), "grid cell offset",
     kBindingCellStart, kBindingCellStartTexels, kUintTexels},
    {&B::cellPrimitives, fromPackedUnless<&P::cellPrimitives, &P::cellTriangles>(),
     "grid cell primitive", kBindingCellPrimitives, kBindingCellPrimitiveTexels, kUintTexels},
    {&B::cellTriangles, kCellTriangles, "grid cell triangle", kBindingCellTriangles,
     kBindingCellTriangleTexels, kUvec4Texels},
    {&B::cellSpheres, fromPacked<&P::cellSpheres>(), "grid cell sphere", kBindingCellSpheres,
     kBindingCellSphereTexels, kVec4Texels},
    {&B::textures, fromPacked<&P::textures>(), "texture", kBindingTextures, kBindingTextureTexels,
     kUvec4Texels},
    {&B::texels, fromPacked<&P::texels>(), "texture texel", kBindingTexels, kBindingImageTexels,
     kVec4Texels},
    {&B::gridEntries, fromPacked<&P::gridEntries>(), "grid voxel map", kBindingGridEntries,
     kBindingGridEntryTexels, kUintTexels},
    {&B::cellBoxes, kCellBoxes, "grid cell box", kBindingCellBoxes, kBindingCellBoxTexels,
     kUvec4Texels},
    {&B::instances, fromPacked<&P::instances>(), "instance", kBindingInstances,
     kBindingInstanceTexels, kVec4Texels},
    {&B::meshGrids, fromPacked<&P::meshGrids>(), "mesh grid", kBindingMeshGrids,
     kBindingMeshGridTexels, kUvec4Texels},
};

} // namespace

SceneBuffers uploadScene(const vk::Context &context, vk::CommandRunner &runner,
                         const PackedScene &packed, const ArrayLimits &limits, UploadPath path) {
    Uploader up(context, runner, limits, path);
    SceneBuffers b;
    b.header =
        up.upload(&packed.header, sizeof(packed.header), false, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    for (const ArrayBinding &a : kArrays)
        b.*a.array = up.array(
            a.source.bytes(packed), [&](std::byte *to) { a.source.write(packed, to); }, a.what,
            a.texels);
    return b;
}

void bindScene(vk::ComputePipeline &pipeline, const SceneBuffers &b, const ArrayLimits &limits) {
    pipeline.bindBuffer(kBindingHeader, b.header.handle());
    for (const ArrayBinding &a : kArrays) {
        const SceneArray &array = b.*a.array;
        pipeline.bindBuffer(a.storageBinding, array.buffer.handle(),
                            std::min<uint64_t>(array.buffer.size(), limits.storageBytes));
        pipeline.bindTexelBuffer(a.texelBinding, array.texels.handle());
    }
}

std::vector<ArrayBytes> arrayBytes(const SceneBuffers &b) {
    std::vector<ArrayBytes> bytes{{"header", b.header.size()}};
    for (const ArrayBinding &a : kArrays)
        bytes.push_back({a.what, (b.*a.array).buffer.size()});
    return bytes;
}

std::vector<VkDescriptorType> traceDescriptorTypes() {
    std::vector<VkDescriptorType> types(kTraceBindingCount, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    types[kBindingAccumImage] = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    types[kBindingAovImage] = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    types[kBindingHeader] = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    types[kBindingTileList] = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    for (const ArrayBinding &a : kArrays)
        types[a.texelBinding] = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    return types;
}

} // namespace prism
