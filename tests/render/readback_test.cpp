// Reading the image back (RayTracer::readback): a frame that copied its image out in its own
// submission (renderFrame's copyOut) reads back what a separate copy reads, AOVs and a region
// included, and never an earlier frame's image; on a CPU device the host reads the image in
// place, and gets what the copy gets; readbackInto fills the caller's arrays with the same.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "gpu_fixture.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"
#include "scene/scene_origin.h"
#include "vk/image.h"

namespace prism::test {
namespace {

// The showcase, centred, and its grid: textures, a mesh, spheres and planes.
class Readback : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        scene = loadScene(std::string(PRISM_SCENES_DIR) + "/showcase.scene");
        centerOnCamera(scene);
        grid = buildGrid(scene, {});
    }
    Scene scene;
    Grid grid;
};

TracerOptions regionWithAovs(bool copiedReadback) {
    TracerOptions options;
    options.maxDepth = 3;
    options.writeAov = true;
    options.region = {5, 3, 41, 30}; // not on tile edges: the image's rows start mid-tile
    options.copiedReadback = copiedReadback;
    return options;
}

TEST_F(Readback, AFrameCopiedOutReadsWhatASeparateCopyReads) {
    for (bool copiedReadback : {false, true}) {
        SCOPED_TRACE(copiedReadback ? "copied" : "in place where the device allows");
        RayTracer tracer(context(), scene, grid, 48, 36, regionWithAovs(copiedReadback));
        Camera moved = scene.camera;
        moved.eye += glm::dvec3(0.4, 0.2, 0.0);
        const Camera cameras[] = {scene.camera, moved, scene.camera};
        for (int k = 0; k < 3; ++k) {
            const Camera &camera = cameras[k], &other = cameras[k == 1 ? 0 : 1];
            tracer.renderFrame(camera, 2);
            TracedImage separate = tracer.readback(2);
            tracer.renderFrame(camera, 2, {}, true);
            TracedImage copiedOut = tracer.readback(2);
            EXPECT_EQ(copiedOut.rgba, separate.rgba);
            EXPECT_EQ(copiedOut.depth, separate.depth);
            EXPECT_EQ(copiedOut.normal, separate.normal);
            // The next frame, another camera, without copyOut: its readback is its own image.
            tracer.renderFrame(other, 2, {}, true);
            tracer.renderFrame(camera, 2);
            EXPECT_EQ(tracer.readback(2).rgba, separate.rgba);
        }
    }
}

// The images read where they are and through a copy are the same, bit for bit, and a CPU
// device reads them in place.
TEST_F(Readback, InPlaceReadsWhatTheCopyReads) {
    RayTracer inPlace(context(), scene, grid, 48, 36, regionWithAovs(false));
    RayTracer copied(context(), scene, grid, 48, 36, regionWithAovs(true));
    EXPECT_FALSE(copied.readsInPlace());
    if (context().properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
        EXPECT_TRUE(inPlace.readsInPlace()) << "lavapipe has linear storage images";
    }
    inPlace.renderFrame(scene.camera, 3, {}, true);
    copied.renderFrame(scene.camera, 3, {}, true);
    TracedImage a = inPlace.readback(3), b = copied.readback(3);
    EXPECT_EQ(a.rgba, b.rgba);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_EQ(a.width, 36u);
    EXPECT_EQ(a.height, 27u);
}

// Linear images have limits of their own: an image past them is not made host-readable (the
// tracer then copies), while the tracer's usual sizes are.
TEST_F(Readback, HostReadableOnlyWithinTheLinearImagesLimits) {
    VkImageUsageFlags usage =
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
    EXPECT_FALSE(vk::Image::hostReadableSupported(context(), 1u << 30, 1, format, usage));
    if (context().properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
        EXPECT_TRUE(vk::Image::hostReadableSupported(context(), 1024, 768, format, usage));
    }
}

// readbackInto writes what readback returns into the caller's arrays (alpha left out), only
// those asked for; depth or normals from a tracer without AOVs are refused.
TEST_F(Readback, IntoTheCallersArraysWhatReadbackReturns) {
    for (bool copiedReadback : {false, true}) {
        SCOPED_TRACE(copiedReadback ? "copied" : "in place where the device allows");
        RayTracer tracer(context(), scene, grid, 48, 36, regionWithAovs(copiedReadback));
        tracer.renderFrame(scene.camera, 2, {}, true);
        TracedImage image = tracer.readback(2);
        size_t pixels = size_t(image.width) * image.height;
        std::vector<float> rgb(pixels * 3, -1.0f), depth(pixels, -1.0f);
        tracer.readbackInto(2, {rgb.data(), depth.data(), nullptr});
        for (size_t i = 0; i < pixels; ++i)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(rgb[i * 3 + c], image.rgba[i * 4 + c]) << "pixel " << i;
        EXPECT_EQ(depth, image.depth);
        std::vector<float> normal(pixels * 3, -1.0f);
        tracer.readbackInto(2, {nullptr, nullptr, normal.data()});
        EXPECT_EQ(normal, image.normal);
    }
    TracerOptions noAovs;
    RayTracer plain(context(), scene, grid, 16, 12, noAovs);
    plain.renderFrame(scene.camera, 1, {}, true);
    std::vector<float> rgb(16 * 12 * 3), depth(16 * 12);
    EXPECT_THROW(plain.readbackInto(1, {rgb.data(), depth.data(), nullptr}), Error);
    plain.readbackInto(1, {rgb.data(), nullptr, nullptr});
    EXPECT_EQ(plain.readback(1).rgba[0], rgb[0]);
}

} // namespace
} // namespace prism::test
