#pragma once
// The data the view library decodes, free of Vulkan calls (only the VkFormat enum), so
// ds_view needs neither the renderer nor the vk layer. renderer/renderer.h includes it:
// FrameResult::inspected is one.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/display.h"
#include "renderer/graph/semantic.h"

namespace ds {

// One graph image as the frame's `inspect` pass read it (Renderer::render's `inspect`): every
// texel as the four floats a shader sampling it sees (depth in r; u32 counts converted to
// float in r, exact below 2^24; UNORM formats in 0..1; HDR as stored), row 0 = top. A
// multisampled image is read at one sample. The camera's depth range comes with it so a
// viewer can linearise depth.
struct InspectedImage {
    std::string name;
    VkFormat format = VK_FORMAT_UNDEFINED;
    graph::Semantic semantic = graph::Semantic::Other;
    graph::Display display{};  // Scalar: how it is shown (graph/display.h)
    uint32_t width = 0, height = 0;
    uint32_t samples = 1;       // of the resource
    uint32_t sample = 0;        // the sample that was read
    std::vector<float> texels;  // width * height * 4
    float znear = 0.1f, zfar = 1000.0f;
    bool reverse_z = true;
};

}  // namespace ds
