#pragma once
// Component-wise EXPECT_NEAR for double vectors, naming the component that is off.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

namespace prism::test {

inline void expectNear(glm::dvec3 a, glm::dvec3 b, double tolerance, const char *what = "") {
    SCOPED_TRACE(what);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(a[c], b[c], tolerance) << "component " << c;
}

} // namespace prism::test
