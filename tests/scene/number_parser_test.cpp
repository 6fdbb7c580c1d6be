// Strict number parsing (engine/scene/number_parser.cpp).
#include <gtest/gtest.h>

#include "scene/number_parser.h"

#include <cfloat>
#include <cmath>

namespace prism {
namespace {

TEST(ParseFloat, AcceptsDecimalFloats) {
    EXPECT_EQ(parseFloat("1").value, 1.0f);
    EXPECT_EQ(parseFloat("-0.5").value, -0.5f);
    EXPECT_EQ(parseFloat("2.5e3").value, 2500.0f);
    EXPECT_EQ(parseFloat("2.5E-1").value, 0.25f);
    EXPECT_EQ(parseFloat(".5").value, 0.5f);
    EXPECT_EQ(parseFloat("5.").value, 5.0f);
    EXPECT_EQ(parseFloat("+1").value, 1.0f);
    EXPECT_EQ(parseFloat("-3.4101800e-003").value, -3.41018e-3f);
    EXPECT_EQ(parseFloat("3.4028235e38").value, FLT_MAX); // rounds to the largest float
    EXPECT_TRUE(parseFloat("1e-45").ok());                // smallest subnormal
}

TEST(ParseFloat, RejectsPartialTokensAndNonNumbers) {
    for (const char *bad :
         {"1.0abc", "abc", "", "-", "+", "1e", "0x10", "1,5", " 1", "1 ", "--1", "+-1", "1..2"})
        EXPECT_EQ(parseFloat(bad).problem, NumberProblem::NotANumber) << bad;
}

TEST(ParseFloat, RejectsNanAndInfinity) {
    for (const char *bad : {"nan", "NaN", "-nan", "inf", "-inf", "Infinity", "+inf"})
        EXPECT_EQ(parseFloat(bad).problem, NumberProblem::NotFinite) << bad;
}

TEST(ParseFloat, RejectsValuesBeyondFloatRangeButRoundsTinyOnesToZero) {
    EXPECT_EQ(parseFloat("1e39").problem, NumberProblem::OutOfRange);
    EXPECT_EQ(parseFloat("-1e39").problem, NumberProblem::OutOfRange);
    EXPECT_EQ(parseFloat("3.5e38").problem, NumberProblem::OutOfRange);
    EXPECT_EQ(parseFloat("1e400").problem, NumberProblem::OutOfRange);
    ParsedFloat tiny = parseFloat("-1e-50");
    EXPECT_TRUE(tiny.ok());
    EXPECT_EQ(tiny.value, 0.0f);
    EXPECT_TRUE(std::signbit(tiny.value));
    EXPECT_TRUE(parseFloat("1e-400").ok());
}

TEST(ParseFloat, DescribesTheProblem) {
    EXPECT_EQ(describeBadNumber("1e39", NumberProblem::OutOfRange),
              "bad number '1e39': out of range for a 32-bit float");
    EXPECT_NE(describeBadNumber("nan", NumberProblem::NotFinite).find("NaN"), std::string::npos);
    EXPECT_NE(describeBadNumber("1x", NumberProblem::NotANumber).find("'1x'"), std::string::npos);
}

// Positions: the same rules as a float, in double precision.
TEST(ParseDouble, KeepsDecimalsUnderTheFloatRules) {
    EXPECT_EQ(parseDouble("1000000.3").value, 1000000.3);
    EXPECT_EQ(parseDouble("+2.5e3").value, 2500.0);
    EXPECT_EQ(parseDouble("-0.1").value, -0.1);
    EXPECT_EQ(parseDouble("1e39").problem, NumberProblem::OutOfRange);
    EXPECT_EQ(parseDouble("nan").problem, NumberProblem::NotFinite);
    EXPECT_EQ(parseDouble("1.0abc").problem, NumberProblem::NotANumber);
    EXPECT_EQ(parseDouble("1e-50").value, 0.0);                    // as a float would have it
    EXPECT_EQ(parseDouble("3.4028235e38").value, double(FLT_MAX)); // rounds to FLT_MAX as a float
}

TEST(ParseInteger, IsStrict) {
    EXPECT_EQ(parseInteger("12").value, 12);
    EXPECT_EQ(parseInteger("-4").value, -4);
    EXPECT_EQ(parseInteger("+4").value, 4);
    EXPECT_EQ(parseInteger("1.0").problem, NumberProblem::NotANumber);
    EXPECT_EQ(parseInteger("1/2").problem, NumberProblem::NotANumber);
    EXPECT_EQ(parseInteger("").problem, NumberProblem::NotANumber);
    EXPECT_EQ(parseInteger("99999999999999999999").problem, NumberProblem::OutOfRange);
}

} // namespace
} // namespace prism
