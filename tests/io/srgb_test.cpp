#include "io/srgb.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prism {
namespace {

TEST(Srgb, EncodeMatchesTheStandardAtKnownPoints) {
    EXPECT_FLOAT_EQ(srgbEncode(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(srgbEncode(1.0f), 1.0f);
    // Linear segment below the 0.0031308 knee: slope 12.92.
    EXPECT_FLOAT_EQ(srgbEncode(0.002f), 0.02584f);
    // 1.055 * 0.5^(1/2.4) - 0.055
    EXPECT_NEAR(srgbEncode(0.5f), 0.735356983f, 1e-6f);
    // 18% grey encodes to about 0.4614.
    EXPECT_NEAR(srgbEncode(0.18f), 0.461356f, 1e-5f);
}

TEST(Srgb, DecodeInvertsEncodeAcrossTheRange) {
    for (int i = 0; i <= 1000; ++i) {
        const float linear = static_cast<float>(i) / 1000.0f;
        EXPECT_NEAR(srgbDecode(srgbEncode(linear)), linear, 2e-6f) << "linear " << linear;
    }
}

TEST(Srgb, BothSegmentsMeetAtTheKnee) {
    // The curve is continuous: each side of 0.0031308 gives nearly the same value.
    EXPECT_NEAR(srgbEncode(0.0031308f), srgbEncode(0.00313081f), 1e-6f);
    EXPECT_NEAR(srgbDecode(0.04045f), srgbDecode(0.0404501f), 1e-6f);
}

TEST(Srgb, EightBitCodesClampAndRoundToNearest) {
    EXPECT_EQ(srgbEncode8(0.0f), 0);
    EXPECT_EQ(srgbEncode8(1.0f), 255);
    EXPECT_EQ(srgbEncode8(0.5f), 188); // 0.73536 * 255 = 187.52
    EXPECT_EQ(srgbEncode8(-3.0f), 0);
    EXPECT_EQ(srgbEncode8(7.0f), 255);
    EXPECT_EQ(srgbEncode8(std::nanf("")), 0);
    // Every code decodes to a linear value that encodes back to the same code.
    for (int code = 0; code <= 255; ++code)
        EXPECT_EQ(srgbEncode8(srgbDecode(static_cast<float>(code) / 255.0f)), code);
}

} // namespace
} // namespace prism
