#pragma once
// Resolving a multisampled depth to the nearest sample (reverse-Z: MAX, else MIN), shared by
// the passes that end with an MSAA depth (depth_prepass; forward with prepass=off). Natively,
// a resolve attachment does it where the device offers the mode; otherwise DepthResolve does
// it in a fullscreen draw writing gl_FragDepth (shaders/depth_resolve.frag), recorded inside
// the pass after its rendering ends. Plumbing, not a pass: passes include it, never each other.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/passes/frame.h"
#include "renderer/passes/pass_util.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds::vk {
struct DeviceReport;
}

namespace ds::passes {

// The resolve mode that keeps the nearest depth, when `report` offers it; NONE otherwise.
VkResolveModeFlagBits native_depth_resolve(const vk::DeviceReport& report, bool reverse_z);
// What the report says: "native-max", "native-min" or "shader".
const char* depth_resolve_name(const vk::DeviceReport& report, bool reverse_z);

class DepthResolve {
  public:
    explicit DepthResolve(const PassServices& services);

    void rebuild_pipelines(vk::DestroyList& retired) { pipelines_.rebuild(retired); }

    struct Target {
        VkImage msaa_image = VK_NULL_HANDLE;  // in DEPTH_STENCIL_ATTACHMENT_OPTIMAL, written
        VkImageView msaa_view = VK_NULL_HANDLE;
        VkImageView depth_view = VK_NULL_HANDLE;  // single-sample, DEPTH_STENCIL_ATTACHMENT_OPTIMAL
        VkExtent2D extent{0, 0};
        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    };
    // Outside any rendering: writes the nearest sample of `msaa_view` into `depth_view`.
    // The MSAA image is sampled in the read-only layout and returned to the attachment layout
    // the graph believes it is in (barriers inside the pass, which the graph cannot see).
    void record(VkCommandBuffer cmd, const FrameInputs& in, const Target& target);

  private:
    ShaderStages compile(uint32_t key) const;
    vk::Pipeline create(uint32_t key, const ShaderStages& stages) const;
    void transition(VkCommandBuffer cmd, VkImage image, bool to_sampled) const;

    PassServices services_;
    vk::Sampler nearest_;
    vk::DescriptorSetLayout set_layout_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool sets_;
    PipelineVariants pipelines_;
};

}  // namespace ds::passes
