// `mesh ... smooth`: vertex normals made for an OBJ without them, on the shader (validation on),
// checked against the analytic sphere they approximate and at the terminator of a coarse one.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "image_compare.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"
#include "temp_dir.h"

namespace prism::test {
namespace {

class SmoothShading : public GpuTest {};

// A unit UV sphere of `segments` around and `rings` from pole to pole, as OBJ text without
// normals: quads in between, triangles at the poles, counter-clockwise from outside.
std::string uvSphereObj(int segments, int rings) {
    std::string obj = "v 0 1 0\n";
    for (int j = 1; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            double theta = M_PI * j / rings, phi = 2.0 * M_PI * i / segments;
            obj += "v " + std::to_string(std::sin(theta) * std::cos(phi)) + " " +
                   std::to_string(std::cos(theta)) + " " +
                   std::to_string(-std::sin(theta) * std::sin(phi)) + "\n";
        }
    obj += "v 0 -1 0\n";
    auto at = [&](int j, int i) { return std::to_string(2 + (j - 1) * segments + i % segments); };
    int last = 2 + (rings - 1) * segments;
    for (int i = 0; i < segments; ++i)
        obj += "f 1 " + at(1, i) + " " + at(1, i + 1) + "\n";
    for (int j = 1; j + 1 < rings; ++j)
        for (int i = 0; i < segments; ++i)
            obj += "f " + at(j, i) + " " + at(j + 1, i) + " " + at(j + 1, i + 1) + " " +
                   at(j, i + 1) + "\n";
    for (int i = 0; i < segments; ++i)
        obj += "f " + at(rings - 1, i + 1) + " " + at(rings - 1, i) + " " + std::to_string(last) +
               "\n";
    return obj;
}

// Seen along -z through a parallel camera 2.4 units high: pixel (i, j) looks at x, y below.
constexpr uint32_t kSize = 64;
constexpr double kHeight = 2.4;
const char *kView = "camera eye 0 0 5 look 0 0 0 ortho 2.4\n"
                    "material m color 1 1 1 ambient 0 diffuse 1 specular 0\n";

glm::dvec2 pixelXY(uint32_t i, uint32_t j) {
    return {(2.0 * (i + 0.5) / kSize - 1.0) * kHeight / 2,
            (1.0 - 2.0 * (j + 0.5) / kSize) * kHeight / 2};
}

// The coarse sphere (12 x 8: facets up to 30 degrees apart) lit from the side. Nothing else is
// in the scene and the smooth surface its normals describe is convex, so no point of it can be
// in shadow: with shadow rays the image must be the image without them (N.L shading alone).
// A shadow ray leaving the flat facet instead (or a horizon taken from the facet's own normal)
// darkens a stair-step band of facets at the terminator: measured 60 of 64x64 pixels, by up
// to 0.19 (either way). Light must not leak either: N.L <= 0 stays black, as without shadows.
TEST_F(SmoothShading, CoarseSphereHasNoStairStepTerminator) {
    TempDir dir;
    dir.write("coarse.obj", uvSphereObj(12, 8));
    Scene scene = loadScene(
        dir.write("s.scene", std::string(kView) + "light -100 40 25\nmesh coarse.obj m smooth\n"));
    TracerOptions noShadows;
    noShadows.shadows = false;
    TracedImage shadowed = renderGpu(context(), scene, kSize, kSize, 1, 1).image;
    TracedImage unshadowed =
        renderGpu(context(), scene, kSize, kSize, 1, 1, GridOptions{}, noShadows).image;
    ImageDifference gpu = compareImages(shadowed.rgba, unshadowed.rgba, 1e-6);
    EXPECT_EQ(gpu.differing, 0u) << describe(gpu);
    std::vector<float> cpu = renderCpu(scene, int(kSize), int(kSize), 1, 1);
    ImageDifference reference = compareImages(cpu, unshadowed.rgba, 2.0 / 255.0);
    EXPECT_EQ(reference.differing, 0u) << describe(reference);
}

// A finely tessellated sphere (64 x 32, 5.6 degrees a facet) made smooth shades as the
// analytic sphere does, away from the silhouette (where the polygon and the circle differ by
// up to 0.5% of the radius: 2 pixels are left out there, the geometry and not the shading).
// Measured largest difference inside: 0.0038 (the interpolated normals are off by a fraction of
// a degree); faceted, the same mesh differs by 0.058. Bound: 0.01, 2.6 times the measurement.
TEST_F(SmoothShading, FineSmoothSphereShadesAsTheAnalyticOne) {
    TempDir dir;
    dir.write("fine.obj", uvSphereObj(64, 32));
    std::string lighting = std::string(kView) + "light -60 40 80\n";
    Scene mesh = loadScene(dir.write("m.scene", lighting + "mesh fine.obj m smooth\n"));
    Scene faceted = loadScene(dir.write("f.scene", lighting + "mesh fine.obj m\n"));
    Scene sphere = loadScene(dir.write("s.scene", lighting + "sphere 0 0 0 1 m\n"));
    TracedImage a = renderGpu(context(), mesh, kSize, kSize, 1, 1).image;
    TracedImage f = renderGpu(context(), faceted, kSize, kSize, 1, 1).image;
    TracedImage b = renderGpu(context(), sphere, kSize, kSize, 1, 1).image;
    double largest = 0.0, largestFaceted = 0.0;
    int compared = 0;
    for (uint32_t j = 0; j < kSize; ++j)
        for (uint32_t i = 0; i < kSize; ++i) {
            glm::dvec2 xy = pixelXY(i, j);
            // Two pixels (0.075 units) inside the unit circle's silhouette.
            if (glm::length(xy) > 1.0 - 2.0 * kHeight / kSize)
                continue;
            size_t p = 4 * (size_t(j) * kSize + i);
            for (int c = 0; c < 3; ++c) {
                largest = std::max(largest, double(std::abs(a.rgba[p + c] - b.rgba[p + c])));
                largestFaceted =
                    std::max(largestFaceted, double(std::abs(f.rgba[p + c] - b.rgba[p + c])));
            }
            ++compared;
        }
    EXPECT_GT(compared, 1500);
    EXPECT_LE(largest, 0.01);
    EXPECT_GT(largestFaceted, 0.01) << "the bound must tell smooth from faceted";
}

} // namespace
} // namespace prism::test
