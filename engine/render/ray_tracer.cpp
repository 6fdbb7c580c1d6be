#include "render/ray_tracer.h"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <string>

#include "core/error.h"
#include "core/timer.h"
#include "render/frame_params.h"
#include "render/loop_bound.h"
#include "shaders/trace.comp.spv.h"
#include "vk/barriers.h"
#include "vk/vk_check.h"

namespace prism {
namespace {

// lavapipe silently ends an invocation's loops after 65,535 iterations in total; the tracer
// stops a little earlier (its own count is conservative) and reports the pixel instead.
constexpr uint32_t kLavapipeLoopBudget = 60000;

constexpr VkDescriptorType kStorageImage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkDescriptorType kStorageBuffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;

template <typename T> size_t bytesOf(const std::vector<T> &v) {
    return v.size() * sizeof(T);
}

uint64_t counterValue(const gpu::GpuStats &stats, int which) {
    const glm::uvec4 &c = which == 0   ? stats.primary
                          : which == 1 ? stats.shadow
                          : which == 2 ? stats.secondary
                                       : stats.budget;
    return uint64_t(c.x) | (uint64_t(c.y) << 32);
}

} // namespace

RayTracer::RayTracer(vk::Context &context, const Scene &scene, const Grid &grid, uint32_t width,
                     uint32_t height, const TracerOptions &options)
    : context_(context), features_(featuresOf(scene)), runner_(context) {
    if (options.maxDepth < 1 || options.maxDepth > 64)
        throw Error("ray depth " + std::to_string(options.maxDepth) + " is outside 1..64");
    features_.maxDepth = options.maxDepth;
    features_.texelBuffers = options.texelBuffers;
    storageLimitOverride_ = options.storageBufferLimit;
    features_.writeAov = options.writeAov;
    features_.shadows = options.shadows;
    features_.reflection = features_.reflection && options.reflection;
    features_.transmission = features_.transmission && options.transmission;
    if (options.loopBudget >= 0)
        features_.loopBudget = uint32_t(options.loopBudget);
    else if (context.isLavapipe())
        features_.loopBudget =
            invocationIterationBound(scene, grid, features_) < kLavapipeLoopBudget
                ? 0u // provably within lavapipe's limit: no counting needed
                : kLavapipeLoopBudget;
    else
        features_.loopBudget = 0u;

    PackedScene packed = packScene(scene, grid);
    sceneBuffers_.push_back(upload(&packed.header, sizeof(packed.header), "scene header"));
    sceneBuffers_.push_back(upload(packed.spheres.data(), bytesOf(packed.spheres), "sphere", 16));
    sceneBuffers_.push_back(upload(packed.planes.data(), bytesOf(packed.planes), "plane"));
    sceneBuffers_.push_back(
        upload(packed.triangles.data(), bytesOf(packed.triangles), "triangle", 16));
    sceneBuffers_.push_back(
        upload(packed.triangleShading.data(), bytesOf(packed.triangleShading), "triangle shading"));
    sceneBuffers_.push_back(upload(packed.materials.data(), bytesOf(packed.materials), "material"));
    sceneBuffers_.push_back(upload(packed.lights.data(), bytesOf(packed.lights), "light"));
    sceneBuffers_.push_back(
        upload(packed.cellStart.data(), bytesOf(packed.cellStart), "grid cell offset", 4));
    sceneBuffers_.push_back(upload(packed.cellPrimitives.data(), bytesOf(packed.cellPrimitives),
                                   "grid cell primitive", 4));
    sceneBuffers_.push_back(upload(packed.textures.data(), bytesOf(packed.textures), "texture"));
    sceneBuffers_.push_back(
        upload(packed.texels.data(), bytesOf(packed.texels), "texture texel", 16));
    stats_ = vk::Buffer(context, sizeof(gpu::GpuStats),
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT, // snapshots for the viewer
                        true);

    createImages(width, height);

    VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
    queryInfo.queryCount = 2;
    VK_CHECK(vkCreateQueryPool(context.device(), &queryInfo, nullptr, &timestamps_));

    vk::ComputePipelineDesc desc;
    desc.spirv = std::span<const uint32_t>(kTraceCompSpv, sizeof(kTraceCompSpv) / 4);
    desc.bindings = {kStorageImage, kStorageImage};
    for (int i = 2; i <= 13; ++i)
        desc.bindings.push_back(kStorageBuffer);
    for (int i = 14; i <= 18; ++i)
        desc.bindings.push_back(VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
    desc.specialization = features_.specialization();
    desc.pushConstantBytes = sizeof(gpu::GpuFrameParams);
    pipeline_ = std::make_unique<vk::ComputePipeline>(context, desc);
    pipeline_->bindStorageImage(0, accum_.view());
    pipeline_->bindStorageImage(1, aov_.view());
    // Both ways of reading the hot arrays are declared by the shader, so both are bound; the
    // TEXEL_BUFFERS constant decides which one it reads. A storage binding never claims more
    // than the device allows (in texel mode the array may be larger).
    VkDeviceSize storageLimit = storageBufferLimit();
    for (uint32_t i = 0; i < sceneBuffers_.size(); ++i)
        pipeline_->bindBuffer(2 + i, sceneBuffers_[i].handle(),
                              std::min(sceneBuffers_[i].size(), storageLimit));
    struct TexelArray {
        uint32_t buffer; // index into sceneBuffers_
        VkFormat format;
    };
    const TexelArray texelArrays[] = {{7, VK_FORMAT_R32_UINT},
                                      {8, VK_FORMAT_R32_UINT},
                                      {1, VK_FORMAT_R32G32B32A32_SFLOAT},
                                      {3, VK_FORMAT_R32G32B32A32_SFLOAT},
                                      {10, VK_FORMAT_R32G32B32A32_SFLOAT}};
    for (uint32_t i = 0; i < std::size(texelArrays); ++i) {
        const vk::Buffer &buffer = sceneBuffers_[texelArrays[i].buffer];
        VkDeviceSize texelSize = texelArrays[i].format == VK_FORMAT_R32_UINT ? 4 : 16;
        texelViews_.emplace_back(
            context, buffer.handle(), texelArrays[i].format,
            std::min(buffer.size(),
                     VkDeviceSize(context.properties().limits.maxTexelBufferElements) * texelSize));
        pipeline_->bindTexelBuffer(14 + i, texelViews_.back().handle());
    }
    pipeline_->bindBuffer(13, stats_.handle());
}

void RayTracer::resize(uint32_t width, uint32_t height) {
    vkDeviceWaitIdle(context_.device()); // no submission may still use the old images
    createImages(width, height);
    pipeline_->bindStorageImage(0, accum_.view());
    pipeline_->bindStorageImage(1, aov_.view());
}

void RayTracer::recordResetCounters(VkCommandBuffer commands) {
    vkCmdFillBuffer(commands, stats_.handle(), 0, VK_WHOLE_SIZE, 0);
    VkMemoryBarrier fill{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    fill.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    fill.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &fill, 0, nullptr, 0, nullptr);
}

void RayTracer::recordCounterSnapshot(VkCommandBuffer commands, VkBuffer target) const {
    VkMemoryBarrier toCopy{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toCopy.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    toCopy.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &toCopy, 0, nullptr, 0, nullptr);
    VkBufferCopy region{0, 0, sizeof(gpu::GpuStats)};
    vkCmdCopyBuffer(commands, stats_.handle(), target, 1, &region);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    // Also orders the next frame's counter updates after this read.
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1,
                         &toHost, 0, nullptr, 0, nullptr);
}

VkDeviceSize RayTracer::counterBytes() {
    return sizeof(gpu::GpuStats);
}

FrameResult RayTracer::decodeCounters(const void *snapshot) {
    gpu::GpuStats stats;
    std::memcpy(&stats, snapshot, sizeof(stats));
    FrameResult result;
    result.rays.primary = counterValue(stats, 0);
    result.rays.shadow = counterValue(stats, 1);
    result.rays.secondary = counterValue(stats, 2);
    result.overBudgetPixels = counterValue(stats, 3);
    return result;
}

RayTracer::~RayTracer() {
    vkDeviceWaitIdle(context_.device());
    if (timestamps_)
        vkDestroyQueryPool(context_.device(), timestamps_, nullptr);
}

VkDeviceSize RayTracer::storageBufferLimit() const {
    VkDeviceSize device = context_.properties().limits.maxStorageBufferRange;
    return storageLimitOverride_ ? std::min(device, storageLimitOverride_) : device;
}

vk::Buffer RayTracer::upload(const void *data, size_t bytes, const char *what,
                             VkDeviceSize texelBytes) {
    const VkPhysicalDeviceLimits &limits = context_.properties().limits;
    if (features_.texelBuffers && texelBytes != 0) {
        uint64_t elements = bytes / texelBytes;
        if (elements > limits.maxTexelBufferElements)
            throw Error(std::string("scene too large for ") + context_.deviceName() + ": the " +
                        what + " array has " + std::to_string(elements) +
                        " texels but one texel buffer may hold at most " +
                        std::to_string(limits.maxTexelBufferElements) +
                        " (maxTexelBufferElements)");
    } else if (bytes > storageBufferLimit()) {
        throw Error(std::string("scene too large for ") + context_.deviceName() + ": the " + what +
                    " array needs " + std::to_string(bytes) +
                    " bytes but one storage buffer may hold at most " +
                    std::to_string(storageBufferLimit()) + " (maxStorageBufferRange)");
    }
    // Vulkan has no empty buffers; unused arrays get one 16-byte element nobody reads.
    VkDeviceSize size = bytes == 0 ? 16 : bytes;
    vk::Buffer target(context_, size,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                          (texelBytes ? VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT : 0),
                      false);
    vk::Buffer staging(context_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    std::memset(staging.mapped(), 0, size);
    if (bytes)
        std::memcpy(staging.mapped(), data, bytes);
    runner_.run([&](VkCommandBuffer commands) {
        VkBufferCopy region{0, 0, size};
        vkCmdCopyBuffer(commands, staging.handle(), target.handle(), 1, &region);
    });
    return target;
}

void RayTracer::createImages(uint32_t width, uint32_t height) {
    width_ = width;
    height_ = height;
    VkImageUsageFlags usage =
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    accum_ = vk::Image(context_, width, height, VK_FORMAT_R32G32B32A32_SFLOAT, usage);
    // The AOV image is full size only when asked for: a scene pays for what it uses.
    bool aov = features_.writeAov;
    aov_ = vk::Image(context_, aov ? width : 1, aov ? height : 1, VK_FORMAT_R32G32B32A32_SFLOAT,
                     usage);
    runner_.run([&](VkCommandBuffer commands) {
        for (const vk::Image *image : {&accum_, &aov_})
            vk::imageBarrier(commands, image->handle(), VK_IMAGE_LAYOUT_UNDEFINED,
                             VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    });
}

void RayTracer::recordSamples(VkCommandBuffer commands, const Camera &camera, uint32_t firstSample,
                              uint32_t count, uint32_t samplesPerPixel) {
    gpu::GpuFrameParams params =
        makeFrameParams(camera, width_, height_, samplesPerPixel, features_.maxDepth);
    pipeline_->bind(commands);
    for (uint32_t s = firstSample; s < firstSample + count; ++s) {
        params.image.z = s;
        vkCmdPushConstants(commands, pipeline_->layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           sizeof(params), &params);
        vkCmdDispatch(commands, (width_ + 7) / 8, (height_ + 7) / 8, 1);
        // Each sample reads the sum the previous one wrote.
        vk::imageBarrier(commands, accum_.handle(), VK_IMAGE_LAYOUT_GENERAL,
                         VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    }
}

FrameResult RayTracer::renderFrame(const Camera &camera, uint32_t samplesPerPixel,
                                   const std::function<void(double)> &progress) {
    FrameResult result;
    uint32_t chunks = progress ? std::min(samplesPerPixel, 20u) : 1u;
    uint32_t done = 0;
    for (uint32_t chunk = 0; chunk < chunks; ++chunk) {
        uint32_t end = uint32_t(uint64_t(samplesPerPixel) * (chunk + 1) / chunks);
        Timer hostTimer;
        runner_.run([&](VkCommandBuffer commands) {
            vkCmdResetQueryPool(commands, timestamps_, 0, 2);
            if (chunk == 0)
                recordResetCounters(commands);
            vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps_, 0);
            recordSamples(commands, camera, done, end - done, samplesPerPixel);
            vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_, 1);
            VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
            toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
            vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                 VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
        });
        double hostMs = hostTimer.elapsedMs();
        uint64_t ticks[2] = {0, 0};
        VkResult queried =
            vkGetQueryPoolResults(context_.device(), timestamps_, 0, 2, sizeof(ticks), ticks,
                                  sizeof(uint64_t), VK_QUERY_RESULT_64_BIT);
        result.gpuMs +=
            queried == VK_SUCCESS && ticks[1] > ticks[0]
                ? double(ticks[1] - ticks[0]) * context_.properties().limits.timestampPeriod * 1e-6
                : hostMs;
        done = end;
        if (progress)
            progress(double(done) / samplesPerPixel);
    }
    FrameResult counted = decodeCounters(stats_.mapped());
    result.rays = counted.rays;
    result.overBudgetPixels = counted.overBudgetPixels;
    return result;
}

TracedImage RayTracer::readback(uint32_t samplesPerPixel) {
    TracedImage out;
    out.width = width_;
    out.height = height_;
    size_t pixels = size_t(width_) * height_;
    bool withAov = features_.writeAov;
    VkDeviceSize bytes = pixels * 16;
    vk::Buffer colour(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    vk::Buffer aov(context_, withAov ? bytes : 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    runner_.run([&](VkCommandBuffer commands) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {width_, height_, 1};
        auto copyOut = [&](const vk::Image &image, VkBuffer target) {
            vk::imageBarrier(commands, image.handle(), VK_IMAGE_LAYOUT_GENERAL,
                             VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                             VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
            vkCmdCopyImageToBuffer(commands, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                   target, 1, &region);
            vk::imageBarrier(commands, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                             VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
        };
        copyOut(accum_, colour.handle());
        if (withAov)
            copyOut(aov_, aov.handle());
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                             0, 1, &toHost, 0, nullptr, 0, nullptr);
    });
    const float *sums = static_cast<const float *>(colour.mapped());
    out.rgba.resize(pixels * 4);
    float scale = 1.0f / float(samplesPerPixel);
    for (size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c)
            out.rgba[i * 4 + c] = sums[i * 4 + c] * scale;
        out.rgba[i * 4 + 3] = 1.0f;
    }
    if (withAov) {
        const float *a = static_cast<const float *>(aov.mapped());
        out.depth.resize(pixels);
        out.normal.resize(pixels * 3);
        for (size_t i = 0; i < pixels; ++i) {
            out.normal[i * 3 + 0] = a[i * 4 + 0];
            out.normal[i * 3 + 1] = a[i * 4 + 1];
            out.normal[i * 3 + 2] = a[i * 4 + 2];
            out.depth[i] = a[i * 4 + 3];
        }
    }
    return out;
}

} // namespace prism
