#pragma once
// The GLFW side of the viewer: the library's lifetime, one window, its input, and the Vulkan
// surface made for it (handed to the engine's vk::Surface owner).
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/surface.h"

struct GLFWwindow;

namespace prism {

// glfwInit/glfwTerminate. Throws prism::Error saying what is missing when there is no display
// or no Vulkan loader.
class GlfwSession {
public:
    GlfwSession();
    ~GlfwSession();
    GlfwSession(const GlfwSession &) = delete;
    GlfwSession &operator=(const GlfwSession &) = delete;
    // Instance extensions the window system needs for a surface.
    static std::vector<const char *> requiredInstanceExtensions();
};

// What happened since the last takeEvents().
struct WindowEvents {
    double scrollY = 0.0;
    std::vector<int> keysPressed; // GLFW_KEY_*, presses only (no repeats)
};

class Window {
public:
    Window(uint32_t width, uint32_t height, const std::string &title);
    ~Window();
    Window(const Window &) = delete;
    Window &operator=(const Window &) = delete;

    GLFWwindow *handle() const { return window_; }
    vk::Surface createSurface(VkInstance instance) const;
    // In pixels; 0x0 while minimised.
    VkExtent2D framebufferSize() const;
    bool shouldClose() const;
    void setTitle(const std::string &title);
    void requestSize(uint32_t width, uint32_t height);
    WindowEvents takeEvents();

    bool keyDown(int key) const;
    bool mouseDown(int button) const;
    void cursor(double &x, double &y) const;

private:
    static void onScroll(GLFWwindow *window, double x, double y);
    static void onKey(GLFWwindow *window, int key, int scancode, int action, int mods);

    GLFWwindow *window_ = nullptr;
    WindowEvents events_;
};

} // namespace prism
