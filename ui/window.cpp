#include "ui/window.h"

#include <algorithm>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>

#include "renderer/common/error.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::ui {
namespace {

std::string glfw_error() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

vk::Semaphore make_semaphore(VkDevice device) {
    auto info = vk::make<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    VkSemaphore s = VK_NULL_HANDLE;
    vk::check(vkCreateSemaphore(device, &info, nullptr, &s), "vkCreateSemaphore");
    return vk::Semaphore(device, s);
}

}  // namespace

std::vector<std::string> Window::instance_extensions() {
    if (!glfwInit()) throw Error("cannot open a window: " + glfw_error());
    if (!glfwVulkanSupported()) throw Error("cannot open a window: GLFW found no Vulkan loader");
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw Error("cannot open a window: " + glfw_error());
    return std::vector<std::string>(names, names + count);
}

Window::Window(uint32_t width, uint32_t height, const std::string& title) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_) throw Error("cannot open a window: " + glfw_error());
    // Before ImGui's GLFW backend installs its callback, which then calls this one too.
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        Window* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
        if (action == GLFW_PRESS) self->pressed_.push_back(key);
        ++self->events_;
    });
    // Any other input counts as activity too (the event loop sleeps without any).
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double, double) { input_event(w); });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int, int, int) { input_event(w); });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double) { input_event(w); });
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned) { input_event(w); });
    glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int) { input_event(w); });
    glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int) { input_event(w); });
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { input_event(w); });
}

void Window::input_event(GLFWwindow* w) {
    ++static_cast<Window*>(glfwGetWindowUserPointer(w))->events_;
}

bool Window::take_input() {
    const bool any = events_ != events_seen_;
    events_seen_ = events_;
    return any;
}

void Window::wait_events(double seconds) const {
    glfwWaitEventsTimeout(seconds);
}

void Window::wake() {
    glfwPostEmptyEvent();
}

void Window::route_mouse_buttons() {
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int mods) {
        Window* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
        self->buttons_.push_back({button, action, mods});
        ++self->events_;
    });
}

bool Window::forward_mouse_buttons() {
    double x = 0, y = 0;
    glfwGetCursorPos(window_, &x, &y);
    const bool jumped = x != forwarded_x_ || y != forwarded_y_;
    forwarded_x_ = x;
    forwarded_y_ = y;
    const bool press = std::any_of(buttons_.begin(), buttons_.end(),
                                   [](const ButtonEvent& e) { return e.action == GLFW_PRESS; });
    if (jumped && press && !held_back_) {  // once: a press while dragging on goes through
        held_back_ = true;
        ++events_;  // this frame hovers at the new place; the next one gets the press
        return true;
    }
    held_back_ = false;
    for (const ButtonEvent& e : buttons_)
        ImGui_ImplGlfw_MouseButtonCallback(window_, e.button, e.action, e.mods);
    buttons_.clear();
    return false;
}

std::vector<int> Window::take_pressed_keys() {
    std::vector<int> keys;
    keys.swap(pressed_);
    return keys;
}

Window::~Window() {
    if (context_) {
        context_->wait_idle();
        destroy_swapchain();
        acquired_.reset();
        if (surface_) vkDestroySurfaceKHR(context_->instance(), surface_, nullptr);
    }
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::should_close() const {
    return glfwWindowShouldClose(window_);
}

void Window::poll_events() const {
    glfwPollEvents();
}

VkExtent2D Window::framebuffer_size() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

void Window::attach(vk::Context& context) {
    context_ = &context;
    vk::check(glfwCreateWindowSurface(context.instance(), window_, nullptr, &surface_),
              "glfwCreateWindowSurface");
    VkBool32 supported = VK_FALSE;
    vk::check(vkGetPhysicalDeviceSurfaceSupportKHR(context.physical_device(),
                                                   context.queue_family(), surface_, &supported),
              "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!supported) throw Error(context.report().candidate.name + " cannot present to this window");
    uint32_t count = 0;
    vk::check(
        vkGetPhysicalDeviceSurfaceFormatsKHR(context.physical_device(), surface_, &count, nullptr),
        "vkGetPhysicalDeviceSurfaceFormatsKHR");
    std::vector<VkSurfaceFormatKHR> formats(count);
    vk::check(vkGetPhysicalDeviceSurfaceFormatsKHR(context.physical_device(), surface_, &count,
                                                   formats.data()),
              "vkGetPhysicalDeviceSurfaceFormatsKHR");
    // UNORM: the viewer's pixels and ImGui's colours are already display-encoded.
    format_ = formats.empty() ? VK_FORMAT_B8G8R8A8_UNORM : formats.front().format;
    for (const VkSurfaceFormatKHR& f : formats)
        if ((f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) &&
            f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
            format_ = f.format;
            break;
        }
    acquired_ = make_semaphore(context.device());
    create_swapchain();
}

void Window::create_swapchain() {
    const VkExtent2D size = framebuffer_size();
    requested_ = size;
    if (size.width == 0 || size.height == 0) return;  // minimised
    VkSurfaceCapabilitiesKHR caps{};
    vk::check(
        vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_->physical_device(), surface_, &caps),
        "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw Error("the window's swapchain images cannot be transfer destinations");
    extent_ = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : size;
    extent_.width = std::clamp(extent_.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height =
        std::clamp(extent_.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    if (extent_.width == 0 || extent_.height == 0) return;
    uint32_t images = caps.minImageCount + 1;
    if (caps.maxImageCount) images = std::min(images, caps.maxImageCount);

    auto info = vk::make<VkSwapchainCreateInfoKHR>(VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR);
    info.surface = surface_;
    info.minImageCount = images;
    info.imageFormat = format_;
    info.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always available
    info.clipped = VK_TRUE;
    vk::check(vkCreateSwapchainKHR(context_->device(), &info, nullptr, &swapchain_),
              "vkCreateSwapchainKHR");
    uint32_t count = 0;
    vk::check(vkGetSwapchainImagesKHR(context_->device(), swapchain_, &count, nullptr),
              "vkGetSwapchainImagesKHR");
    images_.resize(count);
    vk::check(vkGetSwapchainImagesKHR(context_->device(), swapchain_, &count, images_.data()),
              "vkGetSwapchainImagesKHR");
    for (VkImage image : images_) {
        auto view_info = vk::make<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        view_info.image = image;
        view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view_info.format = format_;
        view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        vk::check(vkCreateImageView(context_->device(), &view_info, nullptr, &view),
                  "vkCreateImageView");
        views_.emplace_back(context_->device(), view);
        rendered_.push_back(make_semaphore(context_->device()));
    }
}

void Window::destroy_swapchain() {
    views_.clear();
    rendered_.clear();
    images_.clear();
    if (swapchain_) vkDestroySwapchainKHR(context_->device(), swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
}

bool Window::acquire(Acquired& out, bool& swapchain_changed) {
    const VkExtent2D size = framebuffer_size();
    if (size.width == 0 || size.height == 0) return false;  // minimised
    // Recreate for a new framebuffer size (not for a clamped extent that differs from it).
    if (!swapchain_ || size.width != requested_.width || size.height != requested_.height) {
        context_->wait_idle();
        destroy_swapchain();
        create_swapchain();
        swapchain_changed = true;
        if (!swapchain_) return false;
    }
    uint32_t index = 0;
    const VkResult r = vkAcquireNextImageKHR(context_->device(), swapchain_, UINT64_MAX,
                                             acquired_.handle(), VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        context_->wait_idle();
        destroy_swapchain();
        swapchain_changed = true;
        return false;
    }
    if (r != VK_SUBOPTIMAL_KHR) vk::check(r, "vkAcquireNextImageKHR");
    out = {index,   images_[index],     views_[index].handle(),
           extent_, acquired_.handle(), rendered_[index].handle()};
    return true;
}

void Window::present(const Acquired& a, bool& swapchain_changed) {
    auto info = vk::make<VkPresentInfoKHR>(VK_STRUCTURE_TYPE_PRESENT_INFO_KHR);
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &a.rendered;
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &a.index;
    const VkResult r = context_->present(info);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
        context_->wait_idle();
        destroy_swapchain();
        swapchain_changed = true;
        return;
    }
    vk::check(r, "vkQueuePresentKHR");
}

}  // namespace ds::ui
