#include "render/scene_buffers.h"

#include <algorithm>
#include <cstring>
#include <span>

#include "core/error.h"
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

// Every scene array once: where it comes from, its name in errors, its bindings
// (shared/trace_interface.h) and whether the tracer may read it as texels.
template <auto member> uint64_t bytesOf(const PackedScene &packed) {
    return std::as_bytes(std::span(packed.*member)).size();
}
template <auto member> void copyOf(const PackedScene &packed, std::byte *to) {
    std::span<const std::byte> data = std::as_bytes(std::span(packed.*member));
    std::memcpy(to, data.data(), data.size());
}
// The largest array is not held by the packed scene but written here (PackedScene).
uint64_t cellTriangleBytes(const PackedScene &packed) {
    return cellTriangleCount(packed) * sizeof(gpu::GpuCellTriangle);
}
void writeCellTriangleBytes(const PackedScene &packed, std::byte *to) {
    writeCellTriangles(packed, std::span(reinterpret_cast<gpu::GpuCellTriangle *>(to),
                                         size_t(cellTriangleCount(packed))));
}

struct ArrayBinding {
    SceneArray SceneBuffers::*array;
    uint64_t (*bytes)(const PackedScene &);
    void (*write)(const PackedScene &, std::byte *to);
    const char *what;
    uint32_t storageBinding;
    uint32_t texelBinding;
    TexelLayout texels;
};

using namespace gpu;
using P = PackedScene;
using B = SceneBuffers;
const ArrayBinding kArrays[] = {
    {&B::spheres, bytesOf<&P::spheres>, copyOf<&P::spheres>, "sphere", kBindingSpheres,
     kBindingSphereTexels, kVec4Texels},
    {&B::planes, bytesOf<&P::planes>, copyOf<&P::planes>, "plane", kBindingPlanes,
     kBindingPlaneTexels, kVec4Texels},
    {&B::triangles, bytesOf<&P::triangles>, copyOf<&P::triangles>, "triangle", kBindingTriangles,
     kBindingTriangleTexels, kVec4Texels},
    {&B::triangleShading, bytesOf<&P::triangleShading>, copyOf<&P::triangleShading>,
     "triangle shading", kBindingTriangleShading, kBindingTriangleShadingTexels, kVec4Texels},
    {&B::materials, bytesOf<&P::materials>, copyOf<&P::materials>, "material", kBindingMaterials,
     kBindingMaterialTexels, kVec4Texels},
    {&B::lights, bytesOf<&P::lights>, copyOf<&P::lights>, "light", kBindingLights,
     kBindingLightTexels, kVec4Texels},
    {&B::cellStart, bytesOf<&P::cellStart>, copyOf<&P::cellStart>, "grid cell offset",
     kBindingCellStart, kBindingCellStartTexels, kUintTexels},
    {&B::cellPrimitives, bytesOf<&P::cellPrimitives>, copyOf<&P::cellPrimitives>,
     "grid cell primitive", kBindingCellPrimitives, kBindingCellPrimitiveTexels, kUintTexels},
    {&B::cellTriangles, cellTriangleBytes, writeCellTriangleBytes, "grid cell triangle",
     kBindingCellTriangles, kBindingCellTriangleTexels, kUvec4Texels},
    {&B::cellSpheres, bytesOf<&P::cellSpheres>, copyOf<&P::cellSpheres>, "grid cell sphere",
     kBindingCellSpheres, kBindingCellSphereTexels, kVec4Texels},
    {&B::textures, bytesOf<&P::textures>, copyOf<&P::textures>, "texture", kBindingTextures,
     kBindingTextureTexels, kUvec4Texels},
    {&B::texels, bytesOf<&P::texels>, copyOf<&P::texels>, "texture texel", kBindingTexels,
     kBindingImageTexels, kVec4Texels},
    {&B::gridEntries, bytesOf<&P::gridEntries>, copyOf<&P::gridEntries>, "grid voxel map",
     kBindingGridEntries, kBindingGridEntryTexels, kUintTexels},
    {&B::cellBoxes, bytesOf<&P::cellBoxes>, copyOf<&P::cellBoxes>, "grid cell box",
     kBindingCellBoxes, kBindingCellBoxTexels, kUvec4Texels},
    {&B::instances, bytesOf<&P::instances>, copyOf<&P::instances>, "instance", kBindingInstances,
     kBindingInstanceTexels, kVec4Texels},
    {&B::meshGrids, bytesOf<&P::meshGrids>, copyOf<&P::meshGrids>, "mesh grid", kBindingMeshGrids,
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
            a.bytes(packed), [&](std::byte *to) { a.write(packed, to); }, a.what, a.texels);
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
