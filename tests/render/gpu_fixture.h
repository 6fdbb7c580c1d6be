#pragma once
// One Vulkan context (lavapipe in CI) with validation layers on, shared by a test binary's
// tests; every test fails if any validation message appeared while it ran.
#include <memory>

#include <gtest/gtest.h>

#include "vk/context.h"

namespace prism::test {

inline vk::Context &sharedContext() {
    static std::unique_ptr<vk::Context> context = [] {
        vk::ContextOptions options;
        options.validation = true;
        return std::make_unique<vk::Context>(options);
    }();
    return *context;
}

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override { messagesBefore_ = sharedContext().validationMessageCount(); }
    void TearDown() override {
        EXPECT_EQ(sharedContext().validationMessageCount(), messagesBefore_)
            << "Vulkan validation messages were printed during this test";
    }
    vk::Context &context() { return sharedContext(); }

private:
    uint32_t messagesBefore_ = 0;
};

} // namespace prism::test
