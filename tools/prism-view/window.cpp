#include "window.h"

#include <cstdlib>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "core/error.h"
#include "vk/vk_check.h"

namespace prism {
namespace {

std::string lastGlfwError() {
    const char *description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

} // namespace

GlfwSession::GlfwSession() {
    if (!glfwInit()) {
        std::string why = lastGlfwError();
        const char *display = std::getenv("DISPLAY");
        const char *wayland = std::getenv("WAYLAND_DISPLAY");
        if ((!display || !*display) && (!wayland || !*wayland))
            throw Error("prism-view needs a display, and neither DISPLAY nor WAYLAND_DISPLAY is "
                        "set (" +
                        why +
                        "). Run it in a desktop session, or headless under Xvfb: "
                        "xvfb-run -a prism-view SCENE");
        throw Error("prism-view could not open the display \"" +
                    std::string(display ? display : wayland) + "\": " + why);
    }
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw Error("no Vulkan loader found, so prism-view cannot open a Vulkan window. On "
                    "Debian 12: `sudo apt install libvulkan1 mesa-vulkan-drivers`");
    }
}

GlfwSession::~GlfwSession() {
    glfwTerminate();
}

std::vector<const char *> GlfwSession::requiredInstanceExtensions() {
    uint32_t count = 0;
    const char **names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) // the loader is there, but no driver can draw into windows
        throw Error("no Vulkan driver is installed that can draw into a window (none offers "
                    "VK_KHR_surface for this window system). On Debian 12 `sudo apt install "
                    "mesa-vulkan-drivers` gives lavapipe (runs on the CPU); a GPU needs its "
                    "vendor's Vulkan driver.");
    return std::vector<const char *>(names, names + count);
}

Window::Window(uint32_t width, uint32_t height, const std::string &title) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API); // Vulkan draws, not OpenGL
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_)
        throw Error("could not open a " + std::to_string(width) + "x" + std::to_string(height) +
                    " window: " + lastGlfwError());
    glfwSetWindowUserPointer(window_, this);
    // Installed before the overlay's GLFW backend, which chains to them.
    glfwSetScrollCallback(window_, &Window::onScroll);
    glfwSetKeyCallback(window_, &Window::onKey);
}

Window::~Window() {
    glfwDestroyWindow(window_);
}

vk::Surface Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VK_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
    return vk::Surface(instance, surface);
}

VkExtent2D Window::framebufferSize() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {uint32_t(width), uint32_t(height)};
}

bool Window::shouldClose() const {
    return glfwWindowShouldClose(window_);
}

void Window::setTitle(const std::string &title) {
    glfwSetWindowTitle(window_, title.c_str());
}

void Window::requestSize(uint32_t width, uint32_t height) {
    glfwSetWindowSize(window_, int(width), int(height));
}

WindowEvents Window::takeEvents() {
    WindowEvents taken = std::move(events_);
    events_ = WindowEvents{};
    return taken;
}

bool Window::keyDown(int key) const {
    return glfwGetKey(window_, key) == GLFW_PRESS;
}

bool Window::mouseDown(int button) const {
    return glfwGetMouseButton(window_, button) == GLFW_PRESS;
}

void Window::cursor(double &x, double &y) const {
    glfwGetCursorPos(window_, &x, &y);
}

void Window::onScroll(GLFWwindow *window, double, double y) {
    static_cast<Window *>(glfwGetWindowUserPointer(window))->events_.scrollY += y;
}

void Window::onKey(GLFWwindow *window, int key, int, int action, int) {
    if (action == GLFW_PRESS)
        static_cast<Window *>(glfwGetWindowUserPointer(window))->events_.keysPressed.push_back(key);
}

} // namespace prism
