#pragma once
// Writing .scene text: numbers in a fixed, readable form that every machine prints the same,
// and a file that appears whole or not at all.
#include <cstdint>
#include <filesystem>
#include <string>

#include <glm/glm.hpp>

namespace prism::scenegen {

// Coordinates are generated in integer ticks of 1/10000 unit, so the numbers in a file are
// exact decimals and need no floating-point printing.
constexpr int64_t kTicksPerUnit = 10000;

int64_t toTicks(double value); // nearest tick

// "1.25", "-0.5", "3", "0": at most four decimals, no trailing zeros, never "-0".
std::string formatTicks(int64_t ticks);
std::string formatNumber(double value); // rounded to the nearest tick
std::string formatVec(const glm::dvec3 &v);

// Accumulates lines of a scene file.
class SceneText {
public:
    void line(const std::string &text) { text_ += text + '\n'; }
    void blank() { text_ += '\n'; }
    void comment(const std::string &text) { text_ += "# " + text + '\n'; }
    const std::string &str() const { return text_; }

private:
    std::string text_;
};

// Writes `text` to a temporary file beside `path`, then renames it over `path`. Throws
// prism::Error (leaving nothing behind) when either step fails.
void writeFileAtomically(const std::filesystem::path &path, const std::string &text);

} // namespace prism::scenegen
