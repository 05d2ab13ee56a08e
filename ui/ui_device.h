#pragma once
// The UI's own Vulkan device, on the renderer's physical device: its queue runs UI frames while
// a scene frame occupies the renderer's (lavapipe executes one queue's submissions in order, on
// rasterizer threads of each device's own). It takes only CPU pixels from the renderer. app/
// holds one without naming anything under renderer/vk.
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

namespace ds::vk {
class Context;
}

namespace ds::ui {

class UiDevice {
  public:
    // `device`: "" the first suitable, "N" an index, else a name substring (as the renderer's).
    UiDevice(bool validate, const std::string& device);
    ~UiDevice();
    UiDevice(const UiDevice&) = delete;
    UiDevice& operator=(const UiDevice&) = delete;

    vk::Context& context() { return *context_; }
    // The validation layer's message count, alive after the device is gone.
    std::shared_ptr<const std::atomic<uint64_t>> validation_counter() const;
    void reset();  // destroys the device (the window and presenter first)

  private:
    std::unique_ptr<vk::Context> context_;
};

}  // namespace ds::ui
