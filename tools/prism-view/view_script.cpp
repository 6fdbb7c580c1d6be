#include "view_script.h"

#include <regex>

#include <CLI/CLI.hpp>

#include "core/error.h"
#include "size_option.h"

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

} // namespace

bool ViewScript::empty() const {
    return frames == 0 && resizes.empty() && !orbit && screenshotPath.empty() &&
           reloadPath.empty() && reportEvery == 0;
}

ViewScriptOptions::ViewScriptOptions(CLI::App &app) {
    // The empty group keeps them out of --help: they exist for tests and soak runs.
    app.add_option("--script-frames", frames_)->group("");
    app.add_option("--resize-at", resizes_)->group("");
    app.add_option("--screenshot", screenshot_)->group("");
    app.add_flag("--script-orbit", orbit_)->group("");
    app.add_option("--report-every", reportEvery_)->group("");
    app.add_option("--script-reload", reload_)->group("");
}

ViewScript ViewScriptOptions::script() const {
    ViewScript script;
    script.frames = frames_;
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
    if (!screenshot_.empty() && frames_ == 0)
        throw Error("--screenshot is written at the end of a scripted run (--script-frames N)");
    return script;
}

} // namespace prism
