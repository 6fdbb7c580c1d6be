#include "overlay.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include "core/error.h"
#include "vk/commands.h"
#include "vk/vk_check.h"
#include "window.h"

namespace prism {
namespace {

void checkImGuiVulkan(VkResult result) {
    if (result != VK_SUCCESS)
        vk::throwVulkanError(result, "Dear ImGui Vulkan backend", __FILE__, __LINE__);
}

} // namespace

Overlay::Overlay(Window &window, const vk::Context &context, VkRenderPass renderPass,
                 uint32_t framesInFlight)
    : context_(context), framesInFlight_(framesInFlight) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO &io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini next to the user's files
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 4.0f;
    ImGui_ImplGlfw_InitForVulkan(window.handle(), true);
    // The font texture's descriptor set; the backend allocates nothing else from the pool.
    pool_ = std::make_unique<vk::DescriptorPool>(
        context, std::vector<VkDescriptorPoolSize>{{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4}},
        4);
    initRenderer(renderPass);
}

Overlay::~Overlay() {
    vkDeviceWaitIdle(context_.device());
    if (rendererReady_)
        ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    pool_.reset();
}

void Overlay::initRenderer(VkRenderPass renderPass) {
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context_.instance();
    info.PhysicalDevice = context_.physicalDevice();
    info.Device = context_.device();
    info.QueueFamily = context_.queueFamily();
    info.Queue = context_.queue();
    info.DescriptorPool = pool_->handle();
    info.Subpass = 0;
    // The backend rotates its vertex buffers over ImageCount frames: one more than we keep in
    // flight, so a buffer is never rewritten while the GPU reads it.
    info.MinImageCount = 2;
    info.ImageCount = framesInFlight_ + 1;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = &checkImGuiVulkan;
    if (!ImGui_ImplVulkan_Init(&info, renderPass))
        throw Error("Dear ImGui's Vulkan backend failed to initialise");
    rendererReady_ = true;
    vk::CommandRunner runner(context_);
    runner.run([](VkCommandBuffer commands) { ImGui_ImplVulkan_CreateFontsTexture(commands); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

void Overlay::setRenderPass(VkRenderPass renderPass) {
    vkDeviceWaitIdle(context_.device());
    ImGui_ImplVulkan_Shutdown();
    rendererReady_ = false;
    // A fresh pool: the old font descriptor set is not freed by the backend.
    pool_ = std::make_unique<vk::DescriptorPool>(
        context_, std::vector<VkDescriptorPoolSize>{{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4}},
        4);
    initRenderer(renderPass);
}

bool Overlay::build(const OverlayStats &s, FeatureToggles &toggles, bool visible) {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    FeatureToggles before = toggles;
    if (visible) {
        ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowBgAlpha(0.75f);
        ImGui::Begin("Prism", nullptr,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                         ImGuiWindowFlags_NoFocusOnAppearing);
        ImGui::Text("%.1f FPS  %.2f ms/frame", s.fps, s.msPerFrame);
        ImGui::Text("%.1f Mrays/s", s.mraysPerSecond);
        ImGui::Text("samples %u / %u%s", s.samples, s.samplesTarget,
                    s.samples >= s.samplesTarget ? " (converged)" : "");
        ImGui::Text("grid %s", s.grid.c_str());
        ImGui::TextUnformatted(s.geometry.c_str());
        ImGui::Text("%.1f MB on the device", double(s.sceneBytes) / 1e6);
        if (s.traceScale > 1)
            ImGui::Text("%ux%u (1/%u while moving)  %s", s.width, s.height, s.traceScale,
                        s.presentMode.c_str());
        else
            ImGui::Text("%ux%u  %s", s.width, s.height, s.presentMode.c_str());
        ImGui::TextUnformatted(s.device.c_str());
        ImGui::TextUnformatted(s.scene.c_str());
        if (!s.frame.empty())
            ImGui::Text("%s  ([ and ] step)", s.frame.c_str());
        ImGui::Separator();
        ImGui::Checkbox("shadows", &toggles.shadows);
        ImGui::SameLine();
        ImGui::Checkbox("reflection", &toggles.reflection);
        ImGui::Checkbox("refraction", &toggles.refraction);
        ImGui::SameLine();
        ImGui::Checkbox("grid", &toggles.grid);
        if (s.loopCutPixels > 0)
            ImGui::TextColored(ImVec4(1.0f, 0.4f, 1.0f, 1.0f),
                               "%llu pixels cut by the loop limit (magenta)",
                               static_cast<unsigned long long>(s.loopCutPixels));
        if (!s.sceneError.empty()) {
            ImGui::Separator();
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 36.0f);
            ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", s.sceneError.c_str());
            ImGui::TextUnformatted("(showing the last scene that loaded)");
            ImGui::PopTextWrapPos();
        }
        if (!s.notice.empty())
            ImGui::TextUnformatted(s.notice.c_str());
        ImGui::TextDisabled("WASD/QE move, drag look, wheel FOV, Shift fast");
        ImGui::TextDisabled("R reset  H hide  F5 reload  F12 screenshot");
        ImGui::End();
    }
    ImGui::Render();
    return !(toggles == before);
}

void Overlay::record(VkCommandBuffer commands) {
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), commands);
}

bool Overlay::wantsMouse() const {
    return ImGui::GetIO().WantCaptureMouse;
}
bool Overlay::wantsKeyboard() const {
    return ImGui::GetIO().WantCaptureKeyboard;
}

} // namespace prism
