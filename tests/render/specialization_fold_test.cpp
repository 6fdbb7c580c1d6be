// The tracer's specialization folded into its module on the host (vk/spirv_specialize.h): the
// module keeps only what the constants leave live, and the pipeline made from it renders what
// the driver's own specialization renders, to the bit, whatever features the scene uses.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cache/disk_cache.h"
#include "gpu_fixture.h"
#include "read_file.h"
#include "render/tracer_features.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"
#include "scene/scene_origin.h"
#include "shaders/trace.comp.spv.h"
#include "temp_dir.h"
#include "test_scenes.h"
#include "vk/spirv_specialize.h"

namespace prism::test {
namespace {

const std::filesystem::path kScenes = PRISM_SCENES_DIR;
const std::span<const uint32_t> kTracer(kTraceCompSpv, sizeof(kTraceCompSpv) / 4);

// A scene's features folded: the module that is left, checked to be non-empty.
std::vector<uint32_t> folded(const TracerFeatures &features) {
    std::string error;
    std::vector<uint32_t> out = vk::foldSpecialization(kTracer, features.specialization(), error);
    EXPECT_FALSE(out.empty()) << error;
    EXPECT_TRUE(error.empty()) << error;
    return out;
}

// Spheres alone, nothing else on, against every feature on: the first module is a fraction of
// the tracer, and each feature switched on keeps more of it.
TEST(SpecializationFold, KeepsOnlyWhatTheConstantsLeaveLive) {
    TracerFeatures spheres;
    spheres.kinds = 1u << gpu::kKindSphere;
    spheres.shadows = true;
    spheres.maxDepth = 1;
    TracerFeatures everything = spheres;
    everything.kinds = 0xFu;
    everything.reflection = everything.transmission = everything.textures = true;
    everything.areaLights = everything.vertexNormals = everything.surfaceMaps = true;
    everything.environment = everything.writeAov = everything.resumable = true;
    everything.maxDepth = 5;
    size_t small = folded(spheres).size(), large = folded(everything).size();
    EXPECT_LT(small, kTracer.size() / 2) << "spheres only: less than half the tracer";
    EXPECT_LT(small, large);
    EXPECT_LE(large, kTracer.size());
}

// A module the optimizer cannot read gives nothing, and says why (the pipeline then gets the
// module as it was).
TEST(SpecializationFold, AnUnreadableModuleSaysWhy) {
    std::vector<uint32_t> garbage(kTracer.begin(), kTracer.begin() + 64);
    garbage[0] = 0x12345678; // not SPIR-V's magic number
    std::string error;
    EXPECT_TRUE(vk::foldSpecialization(garbage, TracerFeatures{}.specialization(), error).empty());
    EXPECT_FALSE(error.empty());
}

// Through a store: folded once and kept ("spirv" entries), read back the next time; other
// constants are another entry, never the first one's module; a damaged entry is folded anew.
TEST(SpecializationFold, AFoldedModuleIsStoredAndReadBack) {
    TempDir dir;
    std::vector<std::string> warnings;
    DiskCache store(DiskCacheOptions{dir.path(), uint64_t(1) << 30,
                                     [&](const std::string &w) { warnings.push_back(w); }});
    TracerFeatures spheres;
    spheres.kinds = 1u << gpu::kKindSphere;
    TracerFeatures meshes = spheres;
    meshes.kinds |= 1u << gpu::kKindTriangle;
    std::string error;
    std::vector<uint32_t> first =
        vk::foldSpecializationStored(kTracer, spheres.specialization(), &store, error);
    EXPECT_EQ(first, folded(spheres));
    std::vector<std::filesystem::path> entries;
    for (const auto &e : std::filesystem::directory_iterator(dir.path()))
        entries.push_back(e.path());
    ASSERT_EQ(entries.size(), 1u);
    EXPECT_EQ(entries[0].filename().string().rfind("spirv-", 0), 0u);
    EXPECT_EQ(vk::foldSpecializationStored(kTracer, spheres.specialization(), &store, error),
              first);
    EXPECT_EQ(vk::foldSpecializationStored(kTracer, meshes.specialization(), &store, error),
              folded(meshes));
    EXPECT_NE(folded(meshes), first);
    // A byte of the first entry's module flipped: its checksum fails, it is folded anew.
    std::string bytes = readFile(entries[0]);
    bytes[bytes.size() - 5] ^= 0x5a;
    dir.write(entries[0].filename().string(), bytes);
    EXPECT_EQ(vk::foldSpecializationStored(kTracer, spheres.specialization(), &store, error),
              first);
    EXPECT_EQ(warnings.size(), 1u) << "the damaged entry, said once";
    EXPECT_TRUE(error.empty()) << error;
}

class SpecializationFoldRender : public GpuTest {};

// Spheres and planes with every feature they can have: a texture, normal and bump maps, an
// area light, a mirror, glass, and the environment's sky for rays that miss.
std::string mappedSpheresScene() {
    std::string assets = (kScenes / "..").string();
    return "camera eye 0 2.4 7.2 look 0 1 0 fov 45\n"
           "environment \"" +
           assets +
           "/environments/sky.exr\" intensity 1 rotate 20\n"
           "light -4 6 6 color 0.9 0.88 0.82 radius 0.5\n"
           "light 5 3 4 color 0.35 0.38 0.45\n"
           "material tiles color 0.75 0.72 0.68 specular 0.4 shininess 48 norm \"" +
           assets +
           "/maps/tiles-normal.png\"\n"
           "material studs color 0.55 0.6 0.65 specular 0.3 reflect 0.15 bump \"" +
           assets +
           "/maps/studs-height.png\" bm 0.02\n"
           "material cow color 1 1 1 specular 0.2 texture \"" +
           assets +
           "/models/spot/spot_texture.png\"\n"
           "material glass color 1 1 1 diffuse 0 specular 1 transmit 0.9 ior 1.5\n"
           "material mirror color 0.9 0.9 0.9 diffuse 0.1 specular 0.8 reflect 0.8\n"
           "plane 0 0 -2.5 0 0 1 tiles\n"
           "plane 0 0 0 0 1 0 studs\n"
           "sphere -2.3 0.8 0.6 0.8 tiles\n"
           "sphere 2.3 0.8 0.6 0.8 studs\n"
           "sphere 0 0.7 0.2 0.7 cow\n"
           "sphere 0.9 0.4 1.9 0.4 glass\n"
           "sphere -1 0.3 2 0.3 mirror\n";
}

struct FoldCase {
    std::string name;
    Scene scene;
    const char *grid;
    bool resumable = false;
};

// Each scene's frame (AOVs on, two samples: area lights and jittered pixels) from the folded
// modules and from the driver's specialization: the same image, AOVs and ray counts.
TEST_F(SpecializationFoldRender, FoldedModulesRenderTheSameFrames) {
    TempDir dir;
    std::filesystem::path mapped = dir.write("mapped-spheres.scene", mappedSpheresScene());
    std::vector<FoldCase> cases = {
        {"mapped spheres, regular grid", loadScene(mapped), "regular"},
        {"mapped spheres, adaptive grid", loadScene(mapped), "adaptive"},
        {"rand500", loadScene(kScenes / "rand500.scene"), "auto"},
        {"environment", loadScene(kScenes / "environment.scene"), "adaptive"},
        {"instances", loadScene(kScenes / "instances.scene"), "auto"},
        {"bump maps on meshes", loadScene(kScenes / "bump-maps.scene"), "auto"},
        {"showcase", loadScene(kScenes / "showcase.scene"), "auto"},
        {"stability scene, resumable", stabilityScene(), "adaptive", true},
    };
    for (FoldCase &c : cases) {
        SCOPED_TRACE(c.name);
        centerOnCamera(c.scene);
        Grid grid = buildGrid(c.scene, parseGridOption(c.grid));
        TracerOptions options;
        options.writeAov = true;
        options.resumable = c.resumable;
        options.resumeLaneBudget = c.resumable ? 300 : 0;
        auto render = [&](bool fold) {
            options.foldSpecialization = fold;
            RayTracer tracer(context(), c.scene, grid, 64, 48, options);
            EXPECT_EQ(tracer.specializationFolded(), fold);
            GpuRender out;
            out.frame = tracer.renderFrame(c.scene.camera, 2);
            out.image = tracer.readback(2);
            return out;
        };
        GpuRender withFold = render(true), withoutFold = render(false);
        expectSameFrame(withFold, withoutFold);
        EXPECT_GT(withFold.frame.rays.shadow, 0u);
        if (c.resumable) {
            EXPECT_GT(withFold.frame.resumeDispatches, 0u);
        }
    }
}

} // namespace
} // namespace prism::test
