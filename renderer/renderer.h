#pragma once
// The renderer facade: Settings + Scene + Camera in, pixels and timings out. The next issue
// replaces the frame inside with a render graph; this interface stays.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"
#include "renderer/vk/capabilities.h"

namespace ds {

struct RendererOptions {
    bool validate = false;  // validation layer (+ synchronization validation) and messenger
    std::string device;     // "" = first suitable, "N" = index, else a name substring
};

// One pass of a frame, as measured by the GPU.
struct PassResult {
    std::string name;
    double gpu_ms = 0;  // from two timestamps around the pass
};

struct FrameResult {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;      // final image, sRGB-encoded, tightly packed, top row first;
                                     // empty when the frame was rendered without read-back
    std::vector<PassResult> passes;  // in execution order
    double gpu_ms = 0;               // first pass start to last pass end, from timestamps
    double cpu_ms = 0;               // host time to record and submit the frame (not the wait)
};

enum class ReadBack { Yes, No };  // benchmarks skip the copy to host memory

class Renderer {
  public:
    explicit Renderer(const RendererOptions& options);  // context, device, shader compiler
    ~Renderer();  // explicit teardown order, vkDeviceWaitIdle first
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const vk::DeviceReport& device_report() const;
    // Uploads geometry, materials and textures (+ mips); replaces the previous scene.
    void set_scene(const scene::Scene& scene);
    // Draws one frame at width x height and reads it back (blocks until it is done).
    // Throws ds::Error before set_scene() or for a zero size.
    FrameResult render(const scene::Camera& camera, const Settings& settings, uint32_t width,
                       uint32_t height, ReadBack read_back = ReadBack::Yes);
    uint64_t validation_message_count() const;
    VkInstance instance() const;  // for RenderDoc's device pointer

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace ds
