#include "ui/ui_device.h"

#include "renderer/vk/context.h"
#include "ui/window.h"

namespace ds::ui {

UiDevice::UiDevice(bool validate, const std::string& device)
    : context_(std::make_unique<vk::Context>(
          vk::ContextOptions{.validate = validate,
                             .device = device,
                             .instance_extensions = Window::instance_extensions(),
                             .swapchain = true})) {}

UiDevice::~UiDevice() = default;

std::shared_ptr<const std::atomic<uint64_t>> UiDevice::validation_counter() const {
    return context_->validation_counter();
}

void UiDevice::reset() {
    context_.reset();
}

}  // namespace ds::ui
