#pragma once
// The inspector's window: GLFW (no client API), its Vulkan surface and swapchain. Resizes
// recreate the swapchain; a minimised window (0x0 framebuffer) draws nothing until restored.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/handle.h"

struct GLFWwindow;

namespace ds::vk {
class Context;
}

namespace ds::ui {

class Window {
  public:
    // glfwInit and the instance extensions a surface needs. Throws ds::Error (one line) when
    // there is no display or no Vulkan support in GLFW.
    static std::vector<std::string> instance_extensions();

    Window(uint32_t width, uint32_t height, const std::string& title);
    ~Window();  // destroys the swapchain and surface (after the device is idle), then GLFW
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool should_close() const;
    void poll_events() const;
    // Sleeps until an event arrives, wake() is called or `seconds` pass.
    void wait_events(double seconds = 0.1) const;
    // Whether input arrived (keys, mouse, wheel, text, focus, resize) since the last call.
    bool take_input();
    bool input_pending() const { return events_ != events_seen_; }  // the same, not taken
    // Ends a wait_events() from any thread (the render thread's finished frames).
    static void wake();
    VkExtent2D framebuffer_size() const;
    // Keys pressed since the last call (GLFW codes), each press once. ImGui 1.86 sees a key
    // only while it is down at a frame's start, so a press shorter than a slow frame (lavapipe)
    // would be lost there.
    std::vector<int> take_pressed_keys();
    // Mouse buttons reach ImGui through forward_mouse_buttons() instead of its GLFW callback
    // (call once, after ImGui_ImplGlfw_Init*). A press that arrives in the same poll as a jump
    // of the cursor (a click right after moving: xdotool, a tablet, a fast hand on a slow
    // frame) waits one UI frame: ImGui 1.86 hovers a tab or overlapping item only when the
    // previous frame hovered it too, so the press would otherwise be lost.
    void route_mouse_buttons();
    // Before ImGui_ImplGlfw_NewFrame(): the button events ImGui may have now. True: a press
    // is held back, and the backend, which also reads GLFW's button state, must be told
    // after its NewFrame that no button is down this frame.
    bool forward_mouse_buttons();

    // After the Renderer's context exists: the surface and a first swapchain.
    void attach(vk::Context& context);
    VkFormat format() const { return format_; }

    struct Acquired {
        uint32_t index = 0;
        VkImage image = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
        VkExtent2D extent{0, 0};
        VkSemaphore acquired = VK_NULL_HANDLE;  // the presenter's submit waits on it
        VkSemaphore rendered = VK_NULL_HANDLE;  // and signals this one; present waits on it
    };
    // False when the swapchain had to be recreated (or the window is minimised): skip this
    // frame. `swapchain_changed` is set whenever image views were replaced.
    bool acquire(Acquired& out, bool& swapchain_changed);
    void present(const Acquired& acquired, bool& swapchain_changed);

  private:
    void create_swapchain();
    void destroy_swapchain();

    GLFWwindow* window_ = nullptr;
    static void input_event(GLFWwindow* w);

    std::vector<int> pressed_;  // by the key callback, during poll_events
    struct ButtonEvent {
        int button, action, mods;
    };
    std::vector<ButtonEvent> buttons_;            // routed, not yet forwarded
    double forwarded_x_ = -1, forwarded_y_ = -1;  // the cursor at the last forward
    bool held_back_ = false;                      // the last forward held a press back
    uint64_t events_ = 0, events_seen_ = 0;
    vk::Context* context_ = nullptr;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{0, 0};     // the swapchain's
    VkExtent2D requested_{0, 0};  // the framebuffer size it was made for
    std::vector<VkImage> images_;
    std::vector<vk::ImageView> views_;
    std::vector<vk::Semaphore> rendered_;  // one per swapchain image
    vk::Semaphore acquired_;               // reused: the presenter waits for each frame's fence
};

}  // namespace ds::ui
