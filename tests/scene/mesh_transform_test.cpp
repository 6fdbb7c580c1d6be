// Mesh placement (engine/scene/mesh_transform.cpp): order, exact quarter turns, normals.
#include <gtest/gtest.h>

#include "scene/mesh_transform.h"

#include <cmath>

namespace prism {
namespace {

TEST(MeshTransform, RotationsAreRightHanded) {
    EXPECT_EQ(axisRotation(0, 90) * glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)); // x: y -> z
    EXPECT_EQ(axisRotation(1, 90) * glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0)); // y: z -> x
    EXPECT_EQ(axisRotation(2, 90) * glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)); // z: x -> y
}

TEST(MeshTransform, QuarterTurnsAreExactForAnyMultiple) {
    EXPECT_EQ(axisRotation(2, -90) * glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0));
    EXPECT_EQ(axisRotation(2, 180) * glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0));
    EXPECT_EQ(axisRotation(2, 450) * glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0));
    EXPECT_EQ(axisRotation(2, 360) * glm::dvec3(1, 2, 3), glm::dvec3(1, 2, 3));
    glm::dvec3 r = axisRotation(1, 30) * glm::dvec3(0, 0, 1);
    EXPECT_NEAR(r.x, 0.5, 1e-15);
    EXPECT_NEAR(r.z, std::sqrt(3.0) / 2, 1e-15);
}

TEST(MeshTransform, ScaleThenRotationsInOrderThenTranslate) {
    MeshTransform t;
    t.scale = 2;
    t.rotations = {{0, 90}, {1, 90}}; // x first, then y
    t.translation = {10, 20, 30};
    AffineMap map(t);
    // (0,1,0) -> scale (0,2,0) -> x 90 (0,0,2) -> y 90 (2,0,0) -> translate.
    EXPECT_EQ(map.point({0, 1, 0}), glm::dvec3(12, 20, 30));
    t.rotations = {{1, 90}, {0, 90}}; // y first: (0,2,0) stays, then x 90 -> (0,0,2)
    EXPECT_EQ(AffineMap(t).point({0, 1, 0}), glm::dvec3(10, 20, 32));
}

// `place` stores rotationOf as an instance's rotation: the same product as a mesh line's.
TEST(MeshTransform, RotationOfIsTheMeshLinesRotationsInOrder) {
    EXPECT_EQ(rotationOf({}), glm::dmat3(1.0));
    MeshTransform t;
    t.rotations = {{0, 90}, {1, 90}};
    EXPECT_EQ(rotationOf(t.rotations), axisRotation(1, 90) * axisRotation(0, 90));
    AffineMap map(t);
    EXPECT_EQ(rotationOf(t.rotations) * glm::dvec3(1, 2, 3), map.point(glm::vec3(1, 2, 3)));
}

TEST(MeshTransform, FitsFloatIsTheFloatRange) {
    EXPECT_TRUE(fitsFloat(glm::dvec3(3.4e38, -3.4e38, 0)));
    EXPECT_FALSE(fitsFloat(glm::dvec3(0, 0, -3.5e38)));
}

TEST(MeshTransform, NormalsIgnoreTranslationAndKeepDirectionUnderScale) {
    MeshTransform t;
    t.scale = 4;
    t.rotations = {{0, 90}};
    t.translation = {5, 5, 5};
    glm::dvec3 n = AffineMap(t).normal({0, 0, 1});
    EXPECT_DOUBLE_EQ(n.y, -0.25); // inverse transpose of 4R is R/4; z -> -y under x 90
    EXPECT_DOUBLE_EQ(n.x, 0.0);
    EXPECT_DOUBLE_EQ(n.z, 0.0);
}

TEST(MeshTransform, IdentityLeavesFloatsUntouched) {
    AffineMap identity{MeshTransform{}};
    glm::vec3 p(0.1f, -3.4101800e-003f, 1e-30f);
    EXPECT_EQ(glm::vec3(identity.point(p)), p);
}

} // namespace
} // namespace prism
