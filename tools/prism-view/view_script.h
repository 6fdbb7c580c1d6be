#pragma once
// The hidden command-line options of scripted runs (the Xvfb tests and the soak run), parsed
// apart from the user's options so that ViewOptions holds only what --help lists.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "size_option.h"

namespace CLI {
class App;
}

namespace prism {

// At frame `frame` (0-based), ask the window manager for this client size.
struct ScriptedResize {
    uint32_t frame = 0;
    uint32_t width = 0, height = 0;
};

struct ViewScript {
    uint32_t frames = 0;  // > 0: no input; run at least this many frames, then exit
    double seconds = 0.0; // > 0: no input; run at least this long (and `frames`), then exit
    std::vector<ScriptedResize> resizes;
    bool orbit = false;                   // move the camera every frame (soak run)
    std::filesystem::path screenshotPath; // written (EXR + PNG) when the script ends
    uint32_t reloadFrame = 0;             // at this frame the scene file is replaced by
    std::filesystem::path reloadPath;     // this one and reloaded (as if edited)
    uint32_t reportEvery = 0; // soak: print RSS every N frames, and a summary at the end

    // The soak run's periodic events, each every N frames from frame N on (0: never).
    uint32_t reloadEvery = 0; // rewrite the scene file (a scratch copy!) and reload it
    // > 0: at this frame the camera jumps 1000 view distances back, at the next it returns to
    // the scene's camera; each jump re-centres the scene on the camera (scene_origin.h).
    uint32_t flyAwayFrame = 0;
    uint32_t toggleEvery = 0; // switch one tracer feature, as the overlay's checkboxes do
    uint32_t resizeEvery = 0; // ask for the next size of resizeCycle
    std::vector<ImageSize> resizeCycle;

    // No hidden option was given: a user's session.
    bool empty() const;
    // No user: a frame count or a time limit ends the run.
    bool scripted() const { return frames > 0 || seconds > 0.0; }
};

// Adds the script's options to prism-view's command line, hidden from --help. CLI11 writes
// into this object while it parses, so it must stay where it is until then.
class ViewScriptOptions {
public:
    explicit ViewScriptOptions(CLI::App &app);
    ViewScriptOptions(const ViewScriptOptions &) = delete;
    ViewScriptOptions &operator=(const ViewScriptOptions &) = delete;

    // After the command line is parsed. Throws prism::Error for a malformed value, for a
    // screenshot without --script-frames (it is only written when a script ends), or for a
    // periodic event in a run that no frame count or time limit ends.
    ViewScript script() const;

private:
    uint32_t frames_ = 0;
    double seconds_ = 0.0;
    std::vector<std::string> resizes_;
    std::string screenshot_;
    bool orbit_ = false;
    uint32_t reportEvery_ = 0;
    std::string reload_;
    uint32_t reloadEvery_ = 0;
    uint32_t flyAwayFrame_ = 0;
    uint32_t toggleEvery_ = 0;
    std::string resizeEvery_;
};

} // namespace prism
