// The shipped scenes load cleanly with the primitive counts of the benchmarks they recreate, and
// prism-scenegen regenerates the generated ones byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "read_file.h"
#include "scene/scene_loader.h"
#include "scene_warnings.h"
#include "temp_dir.h"

namespace prism {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(PRISM_ASSETS_DIR) / "scenes";

using test::allWarnings;
using test::readFile;
using test::TempDir;

struct RunResult {
    int exitCode = -1;
    std::string output; // stdout and stderr together
};

// Runs prism-scenegen with `args` (already shell-quoted where needed).
RunResult runScenegen(const std::string &args, const TempDir &dir) {
    std::filesystem::path log = dir.path() / "output.log";
    std::string command =
        std::string("'") + PRISM_SCENEGEN_EXE + "' " + args + " > '" + log.string() + "' 2>&1";
    int status = std::system(command.c_str());
    RunResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.output = readFile(log);
    return result;
}

struct ExpectedCounts {
    const char *name;
    size_t spheres, planes, triangles, lights;
};

// The eight benchmark scenes of the original (SEED_NOTES: primitives 621, 1001, 53, 503, 5003,
// 1057, 4968, 5436) plus the showcase and the Cornell box. Only teapot differs from the
// original's count: the shipped teapot model is finer (assets/scenes/README.md).
const ExpectedCounts kExpected[] = {
    {"scene", 19, 2, 600, 1},  {"grid", 1000, 1, 0, 1},     {"rand50", 50, 3, 0, 1},
    {"rand500", 500, 3, 0, 1}, {"rand5000", 5000, 3, 0, 1}, {"teapot", 0, 1, 6320, 1},
    {"bunny", 0, 0, 4968, 1},  {"objects", 0, 0, 5436, 1},  {"showcase", 4, 1, 12176, 3},
    {"cornell", 2, 0, 36, 1},  {"instances", 1, 1, 0, 2},
};

TEST(ShippedScenes, EveryFileLoadsWithoutWarnings) {
    std::set<std::string> found;
    for (const auto &entry : std::filesystem::directory_iterator(kScenes)) {
        if (entry.path().extension() != ".scene")
            continue;
        found.insert(entry.path().stem().string());
        SCOPED_TRACE(entry.path().string());
        Scene scene = loadScene(entry.path());
        EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
        EXPECT_FALSE(scene.lights.empty());
        EXPECT_GT(scene.finitePrimitiveCount() + scene.planes.size(), 0u);
    }
    std::set<std::string> expected;
    for (const ExpectedCounts &e : kExpected)
        expected.insert(e.name);
    for (const std::string &name : expected)
        EXPECT_TRUE(found.count(name)) << name << ".scene is missing";
}

class ShippedSceneCounts : public testing::TestWithParam<ExpectedCounts> {};

TEST_P(ShippedSceneCounts, MatchTheBenchmark) {
    const ExpectedCounts &e = GetParam();
    Scene scene = loadScene(kScenes / (std::string(e.name) + ".scene"));
    EXPECT_EQ(scene.spheres.size(), e.spheres);
    EXPECT_EQ(scene.planes.size(), e.planes);
    EXPECT_EQ(scene.triangles.size(), e.triangles);
    EXPECT_EQ(scene.lights.size(), e.lights);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedSceneCounts, testing::ValuesIn(kExpected),
                         [](const testing::TestParamInfo<ExpectedCounts> &info) {
                             return std::string(info.param.name);
                         });

TEST(ShippedScenes, SeedScenePrimitiveTotalsAreTheOriginals) {
    const std::pair<const char *, size_t> totals[] = {
        {"scene", 621},     {"grid", 1001},  {"rand50", 53},   {"rand500", 503},
        {"rand5000", 5003}, {"bunny", 4968}, {"objects", 5436}};
    for (const auto &[name, total] : totals) {
        Scene scene = loadScene(kScenes / (std::string(name) + ".scene"));
        EXPECT_EQ(scene.spheres.size() + scene.planes.size() + scene.triangles.size(), total)
            << name;
    }
}

struct Generated {
    const char *file;
    const char *args; // as in assets/scenes/README.md, without -o
};

const Generated kGenerated[] = {
    {"rand50.scene", "random --count 50 --seed 1"},
    {"rand500.scene", "random --count 500 --seed 1"},
    {"rand5000.scene", "random --count 5000 --seed 1"},
    {"grid.scene", "lattice --size 10"},
    {"scene.scene", "mixed"},
    {"objects.scene", "objects"},
};

class Regeneration : public testing::TestWithParam<Generated> {};

TEST_P(Regeneration, IsByteIdenticalToTheShippedFile) {
    const Generated &g = GetParam();
    TempDir dir;
    std::filesystem::path out = dir.path() / g.file;
    RunResult run = runScenegen(std::string(g.args) + " -o '" + out.string() + "'", dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::string shipped = readFile(kScenes / g.file);
    std::string regenerated = readFile(out);
    EXPECT_TRUE(shipped == regenerated)
        << g.file << " differs from `prism-scenegen " << g.args << "`: regenerate it (README.md)";
    // Nothing but the output is left behind (no temporary files).
    size_t files = 0;
    for ([[maybe_unused]] const auto &entry : std::filesystem::directory_iterator(dir.path()))
        ++files;
    EXPECT_EQ(files, 2u); // the scene and output.log
}

INSTANTIATE_TEST_SUITE_P(Scenes, Regeneration, testing::ValuesIn(kGenerated),
                         [](const testing::TestParamInfo<Generated> &info) {
                             std::string name = info.param.file;
                             return name.substr(0, name.find('.'));
                         });

TEST(Scenegen, SeedsChangeTheSpheresAndNothingElseDoes) {
    TempDir dir;
    std::filesystem::path a = dir.path() / "a.scene", b = dir.path() / "b.scene",
                          c = dir.path() / "c.scene";
    ASSERT_EQ(runScenegen("random --count 20 --seed 7 -o '" + a.string() + "'", dir).exitCode, 0);
    ASSERT_EQ(runScenegen("random --seed 7 --count 20 -o '" + b.string() + "'", dir).exitCode, 0);
    ASSERT_EQ(runScenegen("random --count 20 --seed 8 -o '" + c.string() + "'", dir).exitCode, 0);
    EXPECT_EQ(readFile(a), readFile(b));
    EXPECT_NE(readFile(a), readFile(c));
    Scene scene = loadScene(a);
    EXPECT_EQ(scene.spheres.size(), 20u);
    // Every sphere stays inside the box of side 10 above the floor.
    for (const Sphere &s : scene.spheres) {
        EXPECT_GE(s.radius, 0.4f);
        EXPECT_LE(s.radius, 0.8f);
        EXPECT_GE(s.center.y - s.radius, -1e-5f);
        EXPECT_LE(s.center.y + s.radius, 10.0f + 1e-5f);
        EXPECT_LE(std::abs(s.center.x) + s.radius, 5.0f + 1e-5f);
        EXPECT_LE(std::abs(s.center.z) + s.radius, 5.0f + 1e-5f);
    }
}

// The triangle-scaling scene: about the triangles asked for, in the same picture at any count.
TEST(Scenegen, ToriHaveAboutTheTrianglesAskedFor) {
    TempDir dir;
    for (uint32_t triangles : {2000u, 60000u}) {
        std::filesystem::path path = dir.path() / "tori.scene";
        ASSERT_EQ(runScenegen("tori --triangles " + std::to_string(triangles) + " -o '" +
                                  path.string() + "'",
                              dir)
                      .exitCode,
                  0);
        Scene scene = loadScene(path);
        EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
        EXPECT_NEAR(double(scene.triangles.size()), double(triangles), 0.1 * triangles);
        EXPECT_EQ(scene.planes.size(), 1u);
        EXPECT_EQ(scene.camera.eye, glm::dvec3(6.2, 6.4, 16.2)) << "the view does not change";
    }
}

// Shards: that many more triangles, each spanning the whole row (huge beside the tori's), and
// the tori unchanged.
TEST(Scenegen, ToriShardsAreHugeTrianglesThroughTheRow) {
    TempDir dir;
    std::filesystem::path plain = dir.path() / "plain.scene", shards = dir.path() / "shards.scene";
    ASSERT_EQ(runScenegen("tori --triangles 20000 -o '" + plain.string() + "'", dir).exitCode, 0);
    ASSERT_EQ(
        runScenegen("tori --triangles 20000 --shards 6 -o '" + shards.string() + "'", dir).exitCode,
        0);
    Scene a = loadScene(plain), b = loadScene(shards);
    EXPECT_TRUE(b.warnings.empty()) << allWarnings(b);
    ASSERT_EQ(b.triangles.size(), a.triangles.size() + 6);
    double rowLo = 1e300, rowHi = -1e300;
    for (const Triangle &t : a.triangles)
        for (const glm::dvec3 &p : t.p) {
            rowLo = std::min(rowLo, p.x);
            rowHi = std::max(rowHi, p.x);
        }
    for (size_t k = a.triangles.size(); k < b.triangles.size(); ++k) {
        const glm::dvec3 *p = b.triangles[k].p;
        EXPECT_LT(std::min({p[0].x, p[1].x, p[2].x}), rowLo) << "shard " << k << " starts early";
        EXPECT_GT(std::max({p[0].x, p[1].x, p[2].x}), rowHi) << "shard " << k << " ends late";
    }
    EXPECT_NE(readFile(shards).find("--shards 6 -o FILE"), std::string::npos);
}

// The dense single surface of the first-image ladder: an OBJ beside the scene, closed (every
// edge shared by exactly two triangles that run it in opposite directions, so the mesh is
// watertight and consistently wound), every triangle facing away from the centre, none dropped.
TEST(Scenegen, SphereMeshIsOneClosedOutwardMeshInAnObjFile) {
    TempDir dir;
    std::filesystem::path path = dir.path() / "ball.scene";
    ASSERT_EQ(runScenegen("sphere-mesh --triangles 3000 -o '" + path.string() + "'", dir).exitCode,
              0);
    ASSERT_TRUE(std::filesystem::exists(dir.path() / "ball.obj"));
    EXPECT_NE(readFile(path).find("mesh ball.obj ball translate 0 2 0"), std::string::npos);
    Scene scene = loadScene(path);
    EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
    const uint32_t n = 16; // round(sqrt(3000 / 12))
    ASSERT_EQ(scene.triangles.size(), 12u * n * n);
    std::map<std::pair<std::array<double, 3>, std::array<double, 3>>, int> directedEdges;
    auto key = [](const glm::dvec3 &p) { return std::array<double, 3>{p.x, p.y, p.z}; };
    const glm::dvec3 centre(0.0, 2.0, 0.0);
    for (const Triangle &t : scene.triangles) {
        for (const glm::dvec3 &p : t.p)
            EXPECT_NEAR(glm::length(p - centre), 2.0, 1e-6);
        glm::dvec3 normal = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
        EXPECT_GT(glm::dot(normal, (t.p[0] + t.p[1] + t.p[2]) / 3.0 - centre), 0.0);
        for (int e = 0; e < 3; ++e)
            ++directedEdges[{key(t.p[e]), key(t.p[(e + 1) % 3])}];
    }
    for (const auto &[edge, count] : directedEdges) {
        EXPECT_EQ(count, 1) << "an edge run twice the same way";
        EXPECT_EQ(directedEdges.count({edge.second, edge.first}), 1u) << "an open edge";
    }
    EXPECT_EQ(directedEdges.size(), 3u * scene.triangles.size());
}

TEST(Scenegen, HeaderNamesTheCommandThatMadeTheFile) {
    std::string text = readFile(kScenes / "rand500.scene");
    EXPECT_NE(text.find("# Generated by: prism-scenegen random --count 500 --seed 1 "),
              std::string::npos);
}

TEST(Scenegen, HelpExitsZero) {
    TempDir dir;
    RunResult run = runScenegen("--help", dir);
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_NE(run.output.find("random"), std::string::npos);
    EXPECT_NE(run.output.find("lattice"), std::string::npos);
}

TEST(Scenegen, BadArgumentsFailWithoutWritingAnything) {
    TempDir dir;
    const std::string out = " -o '" + (dir.path() / "x.scene").string() + "'";
    const std::vector<std::string> bad = {
        "",                                  // no subcommand
        "teleport" + out,                    // unknown subcommand
        "random --count 10",                 // no output
        "random --count 0" + out,            // too few spheres
        "random --count ten" + out,          // not a number
        "random --count 10 --seed -1" + out, // negative seed
        "random --count 10 --bogus 3" + out, // unknown option
        "random --min-radius 0.9 --max-radius 0.5" + out,
        "random --max-radius 6" + out, // does not fit the box of side 10
        "random --box 0" + out,
        "random --materials 0" + out,
        "lattice --size 0" + out,
        "lattice --radius 0.6 --spacing 1" + out, // spheres would overlap
        "tori --triangles 10" + out,              // fewer than 18 a torus
        "tori --count 0" + out,
        "tori --triangles 30000000" + out,
        "tori --shards 65" + out,
        "sphere-mesh --triangles 5" + out,
        "random -o '" + (dir.path() / "no/such/dir/x.scene").string() + "'",
        "random -o '" + dir.path().string() + "'", // a directory
    };
    for (const std::string &args : bad) {
        RunResult run = runScenegen(args, dir);
        EXPECT_NE(run.exitCode, 0) << args;
        EXPECT_FALSE(run.output.empty()) << args << ": no message";
    }
    size_t files = 0;
    for ([[maybe_unused]] const auto &entry : std::filesystem::directory_iterator(dir.path()))
        ++files;
    EXPECT_EQ(files, 1u); // output.log only
}

} // namespace
} // namespace prism
