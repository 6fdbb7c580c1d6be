#pragma once
// Strict number parsing: the whole token must be the number. A float must be finite and fit a
// 32-bit float (values too small to represent become 0, as in any float conversion).
#include <cstdint>
#include <string>
#include <string_view>

namespace prism {

enum class NumberProblem { None, NotANumber, NotFinite, OutOfRange };

struct ParsedFloat {
    float value = 0.0f;
    NumberProblem problem = NumberProblem::None;
    bool ok() const { return problem == NumberProblem::None; }
};

// A position: parsed in double (a coordinate like 1000000.3 keeps its decimals), under the
// same rules as a float, including its range.
struct ParsedDouble {
    double value = 0.0;
    NumberProblem problem = NumberProblem::None;
    bool ok() const { return problem == NumberProblem::None; }
};

struct ParsedInteger {
    int64_t value = 0;
    NumberProblem problem = NumberProblem::None;
    bool ok() const { return problem == NumberProblem::None; }
};

// Decimal float: optional sign, digits with optional '.', optional exponent ("1", "-0.5",
// "2.5e3", ".5", "+1"). Rejects "nan", "inf", "1.0abc", "0x10", "1e39".
ParsedFloat parseFloat(std::string_view token);

// The same grammar and range as parseFloat, kept in double precision.
ParsedDouble parseDouble(std::string_view token);

// Decimal integer with optional sign; rejects "1.0", "1a" and values beyond 64 bits.
ParsedInteger parseInteger(std::string_view token);

// "bad number 'TOKEN': why" for a problem parseFloat reported.
std::string describeBadNumber(std::string_view token, NumberProblem problem);

// A number as messages show it ("-1", "0.5", "1e+39").
std::string formatNumber(double value);

} // namespace prism
