#pragma once
// The hidden command-line options of scripted runs (the Xvfb tests and the soak run), parsed
// apart from the user's options so that ViewOptions holds only what --help lists.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

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
    uint32_t frames = 0; // > 0: no input; run at least this many frames, then exit
    std::vector<ScriptedResize> resizes;
    bool orbit = false;                   // move the camera every frame (soak run)
    std::filesystem::path screenshotPath; // written (EXR + PNG) when the script ends
    uint32_t reloadFrame = 0;             // at this frame the scene file is replaced by
    std::filesystem::path reloadPath;     // this one and reloaded (as if edited)
    uint32_t reportEvery = 0;             // soak: print RSS every N frames and at the end

    // No hidden option was given: a user's session.
    bool empty() const;
};

// Adds the script's options to prism-view's command line, hidden from --help. CLI11 writes
// into this object while it parses, so it must stay where it is until then.
class ViewScriptOptions {
public:
    explicit ViewScriptOptions(CLI::App &app);
    ViewScriptOptions(const ViewScriptOptions &) = delete;
    ViewScriptOptions &operator=(const ViewScriptOptions &) = delete;

    // After the command line is parsed. Throws prism::Error for a malformed value, or for a
    // screenshot without --script-frames (it is only written when a script ends).
    ViewScript script() const;

private:
    uint32_t frames_ = 0;
    std::vector<std::string> resizes_;
    std::string screenshot_;
    bool orbit_ = false;
    uint32_t reportEvery_ = 0;
    std::string reload_;
};

} // namespace prism
