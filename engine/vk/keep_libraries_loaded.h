#pragma once
// Sanitizer builds only (PRISM_SANITIZE): keeps the shared libraries the Vulkan loader has opened
// (the driver, the layers) in memory until the process exits. The loader unloads them when the
// last instance is destroyed; LeakSanitizer, which runs at exit, then no longer sees their
// globals that still point at their allocations, and reports those as leaks of "<unknown
// module>", which no suppression can name (every Vulkan test failed under the debug preset for
// it). Kept loaded, their memory stays reachable and only real leaks are reported. Elsewhere it
// does nothing.

namespace prism::vk {

void keepVulkanLibrariesLoaded();

} // namespace prism::vk
