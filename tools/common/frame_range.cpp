#include "frame_range.h"

#include <charconv>
#include <set>

#include "core/error.h"

namespace prism {
namespace {

constexpr int kLastFrame = 9'999'999;
constexpr size_t kMostFrames = 1'000'000; // a list no farm would give one process

int frameNumber(std::string_view token, std::string_view item) {
    int value = 0;
    auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (token.empty() || error != std::errc() || end != token.data() + token.size() ||
        value < 0 || value > kLastFrame)
        throw Error("--frames: '" + std::string(item) + "' is not a frame or a range A-B[:STEP] " +
                    "(frames are whole numbers from 0 to " + std::to_string(kLastFrame) + ")");
    return value;
}

// The file name part of a pattern: `#` in a directory name is a directory's own character.
size_t fileNameStart(const std::string &pattern) {
    size_t slash = pattern.find_last_of('/');
    return slash == std::string::npos ? 0 : slash + 1;
}

struct HashRun {
    size_t start = std::string::npos, length = 0;
};

HashRun hashRun(const std::string &pattern) {
    HashRun run;
    size_t from = fileNameStart(pattern);
    for (size_t i = from; i < pattern.size(); ++i) {
        if (pattern[i] != '#')
            continue;
        if (run.start != std::string::npos && i != run.start + run.length)
            throw Error("output '" + pattern +
                        "' has two runs of '#'; one names the frame (as in name.####.exr)");
        if (run.start == std::string::npos)
            run.start = i;
        ++run.length;
    }
    return run;
}

} // namespace

std::vector<int> parseFrameList(std::string_view text) {
    if (text.empty())
        throw Error("--frames: the list is empty (use N, A-B, A-B:STEP or a comma-separated list)");
    std::vector<int> frames;
    std::set<int> seen;
    size_t start = 0;
    while (true) {
        size_t comma = text.find(',', start);
        std::string_view item =
            text.substr(start, comma == std::string_view::npos ? text.size() - start
                                                                : comma - start);
        if (item.empty())
            throw Error("--frames: an empty item in '" + std::string(text) + "'");
        size_t dash = item.find('-');
        int first = 0, last = 0, step = 1;
        if (dash == std::string_view::npos) {
            first = last = frameNumber(item, item);
        } else {
            std::string_view tail = item.substr(dash + 1);
            size_t colon = tail.find(':');
            first = frameNumber(item.substr(0, dash), item);
            last = frameNumber(tail.substr(0, colon), item);
            if (colon != std::string_view::npos) {
                step = frameNumber(tail.substr(colon + 1), item);
                if (step < 1)
                    throw Error("--frames: the step of '" + std::string(item) + "' must be >= 1");
            }
            if (last < first)
                throw Error("--frames: the range '" + std::string(item) +
                            "' runs backwards (write it first-last, as " + std::to_string(last) +
                            "-" + std::to_string(first) + ")");
        }
        for (long frame = first; frame <= last; frame += step) {
            if (!seen.insert(int(frame)).second)
                throw Error("--frames: frame " + std::to_string(frame) + " is listed twice");
            if (frames.size() == kMostFrames)
                throw Error("--frames: more than " + std::to_string(kMostFrames) +
                            " frames in one process; split the range");
            frames.push_back(int(frame));
        }
        if (comma == std::string_view::npos)
            break;
        start = comma + 1;
    }
    return frames;
}

bool hasFrameField(const std::string &pattern) {
    bool hashes = hashRun(pattern).length > 0;
    size_t brace = pattern.find("{frame}");
    if (brace != std::string::npos && pattern.find("{frame}", brace + 1) != std::string::npos)
        throw Error("output '" + pattern + "' names {frame} twice");
    if (hashes && brace != std::string::npos)
        throw Error("output '" + pattern + "' has both '#' and {frame}; use one");
    return hashes || brace != std::string::npos;
}

std::string framePath(const std::string &pattern, int frame) {
    hasFrameField(pattern); // throws on an ambiguous pattern
    std::string number = std::to_string(frame);
    if (size_t brace = pattern.find("{frame}"); brace != std::string::npos)
        return pattern.substr(0, brace) + number + pattern.substr(brace + 7);
    HashRun run = hashRun(pattern);
    if (run.length == 0)
        return pattern;
    if (number.size() < run.length)
        number.insert(0, run.length - number.size(), '0');
    return pattern.substr(0, run.start) + number + pattern.substr(run.start + run.length);
}

std::string tilePath(const std::string &pattern, int tile) {
    std::string out = pattern;
    const std::string field = "{tile}";
    for (size_t at = out.find(field); at != std::string::npos; at = out.find(field, at))
        out.replace(at, field.size(), std::to_string(tile));
    return out;
}

} // namespace prism
