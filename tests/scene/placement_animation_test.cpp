// Keyed placements (format 1.2, docs/scene-format.md "Animation"): `key` lines under a `place`
// line move its instance. At frame 1 the instance is the place line's to the bit, at each key
// exactly what a place line with the key's values makes, between keys each value interpolated as
// the camera's are; bad keys are errors at their line (engine/scene/animation_directives.cpp,
// placement_animation.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "expect_file_error.h"
#include "scene/mesh_transform.h"
#include "scene/placement_animation.h"
#include "scene/scene_loader.h"
#include "scene/scene_origin.h"
#include "temp_dir.h"

namespace prism {
namespace {

using test::expectFileError;
using test::TempDir;

// A tetrahedron off the origin (its prototype is centred on (2.5, 4, 5.5)).
const char *kTetra = "v 1 2 3\nv 4 2 3\nv 1 6 3\nv 1 2 8\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const char *kHead = "camera eye 0 2 -30 look 0 1 0\nmesh m.obj as m\n";

class PlacementAnimation : public ::testing::Test {
protected:
    Scene load(const std::string &body) {
        return loadScene(dir_.write("s.scene", std::string(kHead) + body));
    }
    // The scene's instance 0 placed by a still place line with `keys` (no animation).
    Instance still(const std::string &keys) {
        Scene scene = load("place m " + keys + "\n");
        return scene.instances.at(0);
    }
    void expectError(const std::string &body, int line, const std::string &fragment) {
        SCOPED_TRACE(body);
        std::filesystem::path path = dir_.write("bad.scene", std::string(kHead) + body);
        expectFileError([&] { loadScene(path); }, path.string(), line + 2, fragment);
    }
    void SetUp() override { dir_.write("m.obj", kTetra); }
    TempDir dir_;
};

void expectSameInstance(const Instance &a, const Instance &b) {
    EXPECT_EQ(a.prototype, b.prototype);
    EXPECT_EQ(a.material, b.material);
    EXPECT_EQ(a.scale, b.scale);
    EXPECT_EQ(a.translation, b.translation);
    EXPECT_EQ(a.rotation, b.rotation);
}

TEST_F(PlacementAnimation, KeysMakeATrackAndFrameOneIsThePlaceLine) {
    Scene scene = load("place m rotate y 10 translate 1 0 0\n"
                       "place m translate 5 0 0\n"
                       "place m rotate y 0 translate 0 0 4\n"
                       "key 11 rotate y 90 translate 2 0 4\n"
                       "key 21 scale 2\n");
    ASSERT_EQ(scene.instances.size(), 3u);
    ASSERT_EQ(scene.placementTracks.size(), 1u);
    const PlacementTrack &track = scene.placementTracks[0];
    EXPECT_EQ(track.instance, 2u);
    ASSERT_EQ(track.keys.size(), 3u);
    EXPECT_EQ(track.keys[0].line, 5);
    EXPECT_EQ(track.keys[2].line, 7);
    // A key keeps what it does not name from the key before it.
    EXPECT_EQ(track.keys[2].transform.translation, glm::dvec3(2, 0, 4));
    EXPECT_EQ(track.keys[2].transform.rotations.at(0).degrees, 90.0);
    EXPECT_EQ(track.keys[2].transform.scale, 2.0);
    EXPECT_TRUE(placementsAnimated(scene));
    std::vector<Instance> first = instancesAt(scene, 1.0);
    for (size_t i = 0; i < 3; ++i)
        expectSameInstance(first[i], scene.instances[i]);
    expectSameInstance(instancesAt(scene, -4.0)[2], scene.instances[2]);
}

TEST_F(PlacementAnimation, AtEachKeyTheInstanceIsAPlaceLineWithItsValues) {
    Scene scene = load("place m scale 0.5 rotate x 30 rotate y 10 translate 1 2 3\n"
                       "key 9 rotate x 60 rotate y -45 translate 4 2 0\n"
                       "key 17 scale 1.5\n");
    // Rounded as a centred scene's (the GPU's floats): compare with the still one rounded too.
    auto rounded = [](Instance i) {
        roundToFloat(i);
        return i;
    };
    expectSameInstance(instancesAt(scene, 9.0)[0],
                       rounded(still("scale 0.5 rotate x 60 rotate y -45 translate 4 2 0")));
    expectSameInstance(instancesAt(scene, 17.0)[0],
                       rounded(still("scale 1.5 rotate x 60 rotate y -45 translate 4 2 0")));
    // After the last key the instance holds still.
    expectSameInstance(instancesAt(scene, 400.0)[0], instancesAt(scene, 17.0)[0]);
}

TEST_F(PlacementAnimation, LinearKeysInterpolateEachValueOnItsOwnAndAngleNumbersTurnOnce) {
    Scene scene = load("place m rotate y 0 translate 0 0 0\n"
                       "key 5 rotate y 360 translate 8 0 -4\n");
    Instance half = placementAt(scene, scene.placementTracks[0], 3.0);
    // 0 to 360 degrees: halfway is a half turn, not the same place (a key is a number, not an
    // orientation).
    EXPECT_NEAR(half.rotation[0][0], -1.0, 1e-6);
    EXPECT_NEAR(half.rotation[2][2], -1.0, 1e-6);
    // As on a `mesh` line the mesh turns about its OBJ file's origin, then moves: its centre
    // (2.5, 4, 5.5) half turned about +y is (-2.5, 4, -5.5), plus the translation halfway.
    glm::dvec3 centre = half.toWorld(glm::dvec3(0.0));
    EXPECT_NEAR(glm::length(centre - glm::dvec3(4 - 2.5, 4, -2 - 5.5)), 0.0, 1e-5);
    Instance quarter = placementAt(scene, scene.placementTracks[0], 2.0);
    EXPECT_NEAR(quarter.rotation[2][0], 1.0, 1e-6); // +z turned a quarter about +y: +x
}

TEST_F(PlacementAnimation, CatmullRomPassesThroughTheKeysSmoothly) {
    Scene linear = load("place m translate 0 0 0\nkey 11 translate 10 0 0\n"
                        "key 21 translate 10 0 10\n");
    Scene spline = load("place m translate 0 0 0\nkey 11 translate 10 0 0\n"
                        "key 21 translate 10 0 10\ninterpolate catmull-rom\n");
    glm::dvec3 centre(2.5, 4, 5.5);
    auto where = [&](const Scene &s, double f) {
        return placementAt(s, s.placementTracks[0], f).translation - centre;
    };
    EXPECT_NEAR(where(spline, 11.0).x, 10.0, 1e-5);
    EXPECT_NEAR(where(linear, 6.0).x, 5.0, 1e-5);
    // The spline bends the corner at frame 11: before it z leaves 0 a little, the other way
    // from where it is going, as the tangent through the corner points along +x and +z.
    EXPECT_NE(where(spline, 8.0), where(linear, 8.0));
    double step = where(spline, 11.01).z - where(spline, 10.99).z;
    EXPECT_GT(step, 0.0) << "smooth: z already moving at the key";
}

TEST_F(PlacementAnimation, ASplineThatShrinksTheInstanceAwayIsAnErrorNamingFrameAndKeys) {
    // Scale 1, 0.02, 0.02, 5: the spline undershoots to below 0 between the first two keys.
    Scene scene = load("place m scale 1\nkey 3 scale 0.02\nkey 30 scale 0.02\nkey 31 scale 5\n"
                       "interpolate catmull-rom\n");
    bool threw = false;
    for (double f = 1.0; f <= 31.0 && !threw; f += 0.25) {
        try {
            placementAt(scene, scene.placementTracks[0], f);
        } catch (const Error &e) {
            threw = true;
            EXPECT_NE(std::string(e.what()).find("the placement between the keys of line"),
                      std::string::npos)
                << e.what();
            EXPECT_NE(std::string(e.what()).find("'interpolate linear'"), std::string::npos);
        }
    }
    EXPECT_TRUE(threw);
}

TEST_F(PlacementAnimation, CentringMovesTheTracksWithTheScene) {
    Scene scene = load("place m translate 100 0 0\nkey 11 translate 110 0 0\n");
    Scene centred = scene;
    centerOnCamera(centred);
    expectSameInstance(instancesAt(centred, 1.0)[0], centred.instances[0]);
    glm::dvec3 moved = instancesAt(centred, 11.0)[0].translation + centred.origin;
    glm::dvec3 original = instancesAt(scene, 11.0)[0].translation;
    EXPECT_NEAR(glm::length(moved - original), 0.0, 1e-4);
}

TEST_F(PlacementAnimation, BadKeysAreErrorsAtTheirLine) {
    expectError("place m translate 1 0 0\nkey 5 translate 2 0 0\nkey 3 translate 3 0 0\n", 3,
                "key frame 3 must come after the previous key's frame 5 (line 4): keys go in "
                "time order");
    expectError("place m\nkey 1 scale 2\n", 2, "must come after frame 1 (the place line's)");
    expectError("place m rotate y 10 rotate x 5\nkey 5 rotate y 20\n", 2,
                "a key's rotations must be those of its place line (line 3), about y, x in that "
                "order; this key gives y");
    expectError("place m rotate y 10 rotate x 5\nkey 5 rotate x 1 rotate y 2\n", 2, "about y, x");
    expectError("place m\nkey 5 rotate y 90\n", 2, "has no rotate");
    expectError("place m\nkey 5 scale 0\n", 2, "'scale' must be > 0");
    expectError("place m\nkey 5 eye 1 2 3\n", 2, "unknown key 'eye'");
    expectError("place m\nkey 5 scale 3e38\n", 2,
                "the placement takes the bounding box of prototype 'm' out of the range");
    expectError("place m\nsphere 0 0 0 1\nkey 5 scale 2\n", 3, "'key' must follow the camera line");
    // A camera key after a place line's keys is out of place too: keys go under their line.
    expectError("place m\nkey 5 scale 2\nkey 6 eye 1 2 3\n", 3, "unknown key 'eye'");
}

TEST_F(PlacementAnimation, KeysOfAnEmptyPrototypesPlaceAreReadButMoveNothing) {
    dir_.write("empty.obj", "v 0 0 0\n");
    Scene scene =
        loadScene(dir_.write("e.scene", std::string(kHead) + "mesh empty.obj as nothing\n"
                                                             "place nothing\nkey 5 scale 2\n"));
    EXPECT_TRUE(scene.instances.empty());
    EXPECT_TRUE(scene.placementTracks.empty());
    EXPECT_FALSE(placementsAnimated(scene));
}

} // namespace
} // namespace prism
