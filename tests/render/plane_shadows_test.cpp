// Where on the planes a shadow ray may meet the grid (render/plane_shadows.h): every shadow ray
// that meets a box, from any point of the light, leaving from just off the plane, must start
// inside one of the shadow boxes; the floor away from the shadow must be left out; shadows with
// no bound must be refused.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "render/plane_shadows.h"
#include "shared/gpu_types.h"

namespace prism::test {
namespace {

Aabb boxOf(glm::dvec3 lo, glm::dvec3 hi) {
    Aabb b;
    b.min = lo;
    b.max = hi;
    return b;
}

bool inside(const Aabb &b, const glm::dvec3 &p) {
    return glm::all(glm::lessThanEqual(b.min, p)) && glm::all(glm::lessThanEqual(p, b.max));
}

bool inAny(const std::vector<Aabb> &boxes, const glm::dvec3 &p) {
    for (const Aabb &b : boxes)
        if (inside(b, p))
            return true;
    return false;
}

double maxAbs(const glm::dvec3 &v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Shadow rays made backwards: a point b of a box and a point a of the light fix the line of a
// ray through b; its origin is where that line is at the ray's offset above the plane, as
// surface.glsl's offsetOrigin puts it (PRISM_OFFSET_RELATIVE of the point's largest
// coordinate), and the tile that sees the plane there is the one whose hit is that origin
// dropped onto the plane. That hit must lie in a shadow box.
TEST(PlaneShadows, EveryShadowRayThatMeetsABoxLeavesFromInsideOne) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), zeroOne(0.0, 1.0);
    int checked = 0;
    for (int trial = 0; trial < 60; ++trial) {
        // A plane through a point near the origin, tilted in some trials.
        glm::dvec3 n(0.0, 1.0, 0.0);
        if (trial % 3 != 0)
            n = glm::normalize(glm::dvec3(0.4 * unit(rng), 1.0, 0.4 * unit(rng)));
        glm::dvec3 onPlane(3.0 * unit(rng), 0.5 * unit(rng), 3.0 * unit(rng));
        glm::dvec4 plane(n, glm::dot(n, onPlane));
        auto height = [&](glm::dvec3 p) { return glm::dot(n, p) - plane.w; };
        // Boxes above the plane (one of them dipping through it), the light above them.
        std::vector<Aabb> boxes;
        for (int b = 0; b < 1 + trial % 3; ++b) {
            glm::dvec3 c = onPlane + glm::dvec3(4.0 * unit(rng), 0.0, 4.0 * unit(rng)) +
                           n * (b == 2 ? 0.1 : 0.3 + 1.5 * zeroOne(rng));
            glm::dvec3 half(0.1 + 0.8 * zeroOne(rng), 0.1 + 0.6 * zeroOne(rng),
                            0.1 + 0.8 * zeroOne(rng));
            boxes.push_back(boxOf(c - half, c + half));
        }
        Light light;
        light.position = onPlane + glm::dvec3(5.0 * unit(rng), 0.0, 5.0 * unit(rng)) +
                         n * (4.0 + 3.0 * zeroOne(rng));
        light.radius = trial % 2 == 0 ? 0.0f : float(0.8 * zeroOne(rng));
        std::optional<std::vector<Aabb>> shadows =
            planeShadowBoxes(boxes, {plane}, std::vector<Light>{light});
        ASSERT_TRUE(shadows.has_value()) << "trial " << trial;
        ASSERT_EQ(shadows->size(), boxes.size());
        for (int sample = 0; sample < 400; ++sample) {
            const Aabb &box = boxes[size_t(sample) % boxes.size()];
            glm::dvec3 b = box.min + (box.max - box.min) *
                                         glm::dvec3(zeroOne(rng), zeroOne(rng), zeroOne(rng));
            // Corners and faces too, where the hull is tight.
            if (sample % 4 == 0)
                b = glm::mix(box.min, box.max, glm::dvec3(rng() % 2, rng() % 2, rng() % 2));
            glm::dvec3 u = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)) + 1e-9);
            glm::dvec3 a = light.position + double(light.radius) * u;
            if (height(b) <= 0.0 || height(a) <= height(b))
                continue;
            // The ray's line dropped to the plane, then its origin lifted by the offset there.
            glm::dvec3 hit = a + (b - a) * (height(a) / (height(a) - height(b)));
            double e = PRISM_OFFSET_RELATIVE * maxAbs(hit);
            if (height(b) <= e)
                continue; // b would lie behind the lifted origin
            glm::dvec3 origin = a + (b - a) * ((height(a) - e) / (height(a) - height(b)));
            glm::dvec3 seenAt = origin - e * n;
            ++checked;
            ASSERT_TRUE(inAny(*shadows, seenAt))
                << "trial " << trial << ": a shadow ray from " << seenAt.x << "," << seenAt.y << ","
                << seenAt.z << " meets a box outside every shadow box";
        }
    }
    EXPECT_GT(checked, 10000);
}

// A light to one side: the shadow falls away from it, and the floor between the light's foot
// and the box, and beyond the shadow, is not in it.
TEST(PlaneShadows, TheFloorOutsideTheShadowIsLeftOut) {
    std::vector<Aabb> boxes{boxOf({-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5})};
    Light light;
    light.position = {-4.0, 4.0, 0.0};
    std::optional<std::vector<Aabb>> shadows =
        planeShadowBoxes(boxes, {glm::dvec4(0.0, 1.0, 0.0, 0.0)}, {light});
    ASSERT_TRUE(shadows.has_value());
    // The top's far edge falls at x = -4 + 4.5 * 4 / 3 = 2.
    EXPECT_TRUE(inAny(*shadows, {1.9, 0.0, 0.0}));
    EXPECT_TRUE(inAny(*shadows, {-0.4, 0.0, 0.4}));
    EXPECT_FALSE(inAny(*shadows, {-3.0, 0.0, 0.0})); // towards the light's foot
    EXPECT_FALSE(inAny(*shadows, {-4.0, 0.0, 0.0})); // the foot itself
    EXPECT_FALSE(inAny(*shadows, {2.2, 0.0, 0.0}));
    EXPECT_FALSE(inAny(*shadows, {1.0, 0.0, 1.5}));
}

// Where a box reaches the light's height (or the light's sphere reaches down to the box, or
// the light lies on the plane) its shadow has no bound: the caller must not leave any plane
// tile without the grid.
TEST(PlaneShadows, ShadowsWithNoBoundAreRefused) {
    glm::dvec4 floor(0.0, 1.0, 0.0, 0.0);
    std::vector<Aabb> tall{boxOf({-0.5, 0.0, -0.5}, {0.5, 5.0, 0.5})};
    std::vector<Aabb> low{boxOf({-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5})};
    Light overhead;
    overhead.position = {3.0, 4.0, 0.0};
    EXPECT_FALSE(planeShadowBoxes(tall, {floor}, {overhead}).has_value());
    EXPECT_TRUE(planeShadowBoxes(low, {floor}, {overhead}).has_value());
    Light big = overhead;
    big.position.y = 1.5;
    big.radius = 0.6f; // the box grown by 0.6 reaches y = 1.6
    EXPECT_FALSE(planeShadowBoxes(low, {floor}, {big}).has_value());
    big.radius = 0.4f;
    EXPECT_TRUE(planeShadowBoxes(low, {floor}, {big}).has_value());
    Light onFloor;
    onFloor.position = {3.0, 0.0, 0.0};
    EXPECT_FALSE(planeShadowBoxes(low, {floor}, {onFloor}).has_value());
    // Below the floor, lighting its underside: the box above the floor projects between.
    Light under;
    under.position = {0.0, -3.0, 0.0};
    EXPECT_TRUE(planeShadowBoxes(low, {floor}, {under}).has_value());
    // Nothing to cast a shadow: nothing to refuse.
    std::optional<std::vector<Aabb>> none = planeShadowBoxes({}, {floor}, {overhead});
    ASSERT_TRUE(none.has_value());
    EXPECT_TRUE(none->empty());
}

// Past kMaxPlaneShadowBoxes the boxes are projected as one, per plane and light, and every
// box's shadow is still inside.
TEST(PlaneShadows, ManyBoxesAreProjectedAsTheirUnion) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 300; ++i) {
        double x = -3.0 + 0.02 * i;
        boxes.push_back(boxOf({x, 0.2, -0.01}, {x + 0.01, 0.3, 0.01}));
    }
    std::vector<glm::dvec4> planes{glm::dvec4(0.0, 1.0, 0.0, 0.0), glm::dvec4(0.0, 0.0, 1.0, -2.0)};
    std::vector<Light> lights(120);
    for (size_t i = 0; i < lights.size(); ++i)
        lights[i].position = {0.05 * double(i), 5.0, 3.0};
    ASSERT_GT(boxes.size() * planes.size() * lights.size(), kMaxPlaneShadowBoxes);
    std::optional<std::vector<Aabb>> shadows = planeShadowBoxes(boxes, planes, lights);
    ASSERT_TRUE(shadows.has_value());
    EXPECT_EQ(shadows->size(), planes.size() * lights.size());
    for (const Light &light : lights) {
        // Straight down from the light through the middle of the first and the last box.
        for (const Aabb &box : {boxes.front(), boxes.back()}) {
            glm::dvec3 b = 0.5 * (box.min + box.max);
            glm::dvec3 hit = light.position +
                             (b - light.position) * (light.position.y / (light.position.y - b.y));
            EXPECT_TRUE(inAny(*shadows, hit));
        }
    }
}

} // namespace
} // namespace prism::test
