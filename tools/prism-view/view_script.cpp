#include "view_script.h"

#include <algorithm>
#include <regex>

#include <CLI/CLI.hpp>

#include "core/error.h"

namespace prism {
namespace {

ScriptedResize parseResize(const std::string &text) {
    std::smatch m;
    static const std::regex pattern("([0-9]{1,9}):(.*)");
    if (!std::regex_match(text, m, pattern))
        throw Error("--resize-at must look like FRAME:WxH, got \"" + text + "\"");
    ImageSize size = parseSizeOption(m[2], "--resize-at");
    return {uint32_t(std::stoul(m[1])), size.width, size.height};
}

// "N:WxH,WxH,...": every N frames the next size, round and round.
void parseResizeCycle(const std::string &text, ViewScript &script) {
    const char *option = "--script-resize-every";
    std::smatch m;
    static const std::regex pattern("([0-9]{1,9}):(.+)");
    if (!std::regex_match(text, m, pattern))
        throw Error(std::string(option) + " must look like N:WxH[,WxH...], got \"" + text + "\"");
    script.resizeEvery = uint32_t(std::stoul(m[1]));
    if (script.resizeEvery == 0)
        throw Error(std::string(option) + " needs N >= 1, got \"" + text + "\"");
    std::string sizes = m[2];
    for (size_t start = 0; start <= sizes.size();) {
        size_t comma = std::min(sizes.find(',', start), sizes.size());
        script.resizeCycle.push_back(parseSizeOption(sizes.substr(start, comma - start), option));
        start = comma + 1;
    }
}

} // namespace

bool ViewScript::empty() const {
    return frames == 0 && seconds == 0.0 && resizes.empty() && !orbit && screenshotPath.empty() &&
           reloadPath.empty() && reportEvery == 0 && reloadEvery == 0 && toggleEvery == 0 &&
           resizeEvery == 0 && flyAwayFrame == 0;
}

ViewScriptOptions::ViewScriptOptions(CLI::App &app) {
    // The empty group keeps them out of --help: they exist for tests and soak runs.
    app.add_option("--script-frames", frames_)->group("");
    app.add_option("--script-seconds", seconds_)->check(CLI::PositiveNumber)->group("");
    app.add_option("--resize-at", resizes_)->group("");
    app.add_option("--screenshot", screenshot_)->group("");
    app.add_flag("--script-orbit", orbit_)->group("");
    app.add_option("--report-every", reportEvery_)->group("");
    app.add_option("--script-reload", reload_)->group("");
    app.add_option("--script-reload-every", reloadEvery_)->check(CLI::PositiveNumber)->group("");
    app.add_option("--script-toggle-every", toggleEvery_)->check(CLI::PositiveNumber)->group("");
    app.add_option("--script-resize-every", resizeEvery_)->group("");
    app.add_option("--script-fly-away", flyAwayFrame_)->check(CLI::PositiveNumber)->group("");
}

ViewScript ViewScriptOptions::script() const {
    ViewScript script;
    script.frames = frames_;
    script.seconds = seconds_;
    script.orbit = orbit_;
    script.reportEvery = reportEvery_;
    for (const std::string &text : resizes_)
        script.resizes.push_back(parseResize(text));
    script.screenshotPath = screenshot_;
    if (!reload_.empty()) {
        size_t colon = reload_.find(':');
        if (colon == std::string::npos || colon == 0 ||
            reload_.find_first_not_of("0123456789") != colon)
            throw Error("--script-reload must look like FRAME:PATH, got \"" + reload_ + "\"");
        script.reloadFrame = uint32_t(std::stoul(reload_.substr(0, colon)));
        script.reloadPath = reload_.substr(colon + 1);
    }
    script.reloadEvery = reloadEvery_;
    script.toggleEvery = toggleEvery_;
    script.flyAwayFrame = flyAwayFrame_;
    if (!resizeEvery_.empty())
        parseResizeCycle(resizeEvery_, script);
    if (!screenshot_.empty() && frames_ == 0)
        throw Error("--screenshot is written at the end of a scripted run (--script-frames N)");
    // Reloads and toggles stand in for a user's input, which a run without an end still takes.
    bool periodic = script.reloadEvery > 0 || script.toggleEvery > 0 || script.resizeEvery > 0 ||
                    script.flyAwayFrame > 0;
    if (periodic && !script.scripted())
        throw Error("--script-reload-every, --script-toggle-every, --script-resize-every and "
                    "--script-fly-away need --script-frames N or --script-seconds S");
    // Both would rewrite or replace the scene file; the soak's edits expect the original.
    if (script.reloadEvery > 0 && !script.reloadPath.empty())
        throw Error("--script-reload-every rewrites the scene file; it cannot be combined with "
                    "--script-reload");
    return script;
}

} // namespace prism
