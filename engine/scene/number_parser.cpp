#include "scene/number_parser.h"

#include <cfloat>
#include <charconv>
#include <cmath>
#include <sstream>
#include <system_error>

namespace prism {
namespace {

// std::from_chars takes no leading '+'; accept it before a digit or '.' only.
std::string_view dropPlusSign(std::string_view token) {
    if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+')
        token.remove_prefix(1);
    return token;
}

bool hasNegativeExponent(std::string_view token) {
    size_t e = token.find_first_of("eE");
    return e != std::string_view::npos && e + 1 < token.size() && token[e + 1] == '-';
}

} // namespace

ParsedFloat parseFloat(std::string_view token) {
    std::string_view digits = dropPlusSign(token);
    const char *first = digits.data();
    const char *last = first + digits.size();
    float value = 0.0f;
    auto [end, ec] = std::from_chars(first, last, value, std::chars_format::general);
    if (ec == std::errc::invalid_argument || end != last)
        return {0.0f, NumberProblem::NotANumber};
    if (ec == std::errc::result_out_of_range) {
        // from_chars reports underflow and overflow alike; underflow is a fine 0.
        double wide = 0.0;
        auto [wideEnd, wideEc] = std::from_chars(first, last, wide, std::chars_format::general);
        bool underflow =
            wideEc == std::errc() ? std::fabs(wide) < 1.0 : hasNegativeExponent(digits);
        if (!underflow || wideEnd != last)
            return {0.0f, NumberProblem::OutOfRange};
        return {digits[0] == '-' ? -0.0f : 0.0f, NumberProblem::None};
    }
    if (!std::isfinite(value)) // "nan", "inf", "infinity"
        return {0.0f, NumberProblem::NotFinite};
    return {value, NumberProblem::None};
}

ParsedDouble parseDouble(std::string_view token) {
    // parseFloat does the checking (grammar, finiteness, the float range); the digits are then
    // read again in double.
    ParsedFloat checked = parseFloat(token);
    if (!checked.ok())
        return {0.0, checked.problem};
    if (checked.value == 0.0f) // includes a float underflow, which the rules round to 0
        return {double(checked.value), NumberProblem::None};
    std::string_view digits = dropPlusSign(token);
    double value = 0.0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value,
                                     std::chars_format::general);
    if (ec != std::errc() || end != digits.data() + digits.size() || std::fabs(value) > FLT_MAX)
        return {double(checked.value), NumberProblem::None}; // a hair above FLT_MAX: as a float
    return {value, NumberProblem::None};
}

ParsedInteger parseInteger(std::string_view token) {
    std::string_view digits = dropPlusSign(token);
    const char *first = digits.data();
    const char *last = first + digits.size();
    int64_t value = 0;
    auto [end, ec] = std::from_chars(first, last, value);
    if (ec == std::errc::invalid_argument || end != last)
        return {0, NumberProblem::NotANumber};
    if (ec == std::errc::result_out_of_range)
        return {0, NumberProblem::OutOfRange};
    return {value, NumberProblem::None};
}

std::string describeBadNumber(std::string_view token, NumberProblem problem) {
    std::string message = "bad number '" + std::string(token) + "'";
    switch (problem) {
    case NumberProblem::NotANumber:
        return message + ": not a decimal number";
    case NumberProblem::NotFinite:
        return message + ": NaN and infinity are not allowed";
    case NumberProblem::OutOfRange:
        return message + ": out of range for a 32-bit float";
    case NumberProblem::None:
        break;
    }
    return message;
}

std::string formatNumber(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

} // namespace prism
