#pragma once
// Frame lists and per-frame output names, as renderers on farms write them: `--frames 1-240`,
// `1-240:2` (every second frame), `1,5,10-20`; outputs `turntable.####.exr` (Blender's
// zero-padded `#`) or `shot_{frame}.exr`.
#include <string>
#include <string_view>
#include <vector>

namespace prism {

// The frames of `text` in the order written: comma-separated items, each N or A-B[:STEP]
// (A <= B, STEP >= 1). Frames are whole numbers from 0 to 9,999,999. Throws prism::Error
// saying what is wrong (an empty item, a range that runs backwards, a frame listed twice, ...).
std::vector<int> parseFrameList(std::string_view text);

// Whether `pattern` names a frame: a run of `#` in its file name, or `{frame}` anywhere.
// Throws prism::Error when it holds both, or more than one of either.
bool hasFrameField(const std::string &pattern);

// `pattern` with its frame field replaced: `#` runs by the frame zero-padded to the run's
// length (#### -> 0007; a longer number is written whole), `{frame}` by the plain number.
// A pattern without a field is returned as it is.
std::string framePath(const std::string &pattern, int frame);

// `pattern` with each `{tile}` replaced by `tile` (prism-render --tile I/N: I); as it is without.
std::string tilePath(const std::string &pattern, int tile);

} // namespace prism
