#pragma once
// What the passes share that is not a pass (a pass never includes another pass): per-frame
// descriptor sets, attachments, fullscreen pipelines, the depth resolve mode, and the u32
// count images of count_fragments=on. Pipeline variants: pipeline_variants.h.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/pipeline_variants.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/frame.h"
#include "renderer/vk/pipeline.h"

namespace ds::vk {
class Context;
struct DeviceReport;
}  // namespace ds::vk
namespace ds::shader {
class Compiler;
struct Define;
}  // namespace ds::shader

namespace ds {
class HostReadback;
}

namespace ds::passes {

// Descriptor sets that live for one frame. A pool per frame in flight, reset when its slot
// comes round again: vk::FrameRing::begin() has waited for that slot's previous frame.
class FrameDescriptorPool {
  public:
    FrameDescriptorPool(vk::Context& context, uint32_t max_sets,
                        std::span<const VkDescriptorPoolSize> sizes, const char* name);
    VkDescriptorSet allocate(uint64_t frame_number, VkDescriptorSetLayout layout);

  private:
    std::array<vk::DescriptorPool, vk::FrameRing::kFramesInFlight> pools_;
    std::array<uint64_t, vk::FrameRing::kFramesInFlight> frames_;
};

// A pipeline made for `target` (graph::PassContext::target()): its colour slots (slot 0
// blended with `blend`), its depth format, and inside a subpass group the render pass and
// subpass.
void apply_target(vk::GraphicsPipelineBuilder& builder, const graph::RenderTarget& target,
                  vk::Blend blend = vk::Blend::None);
// The dynamic depth state every pipeline declares (pipeline.h), in one call.
void set_depth_state(VkCommandBuffer cmd, bool test, bool write, VkCompareOp compare);

// A fullscreen triangle (shaders/fullscreen.vert) with `fragment`: tonemap, skybox, depth
// resolve, made for the target of the pass that draws it, at `samples`.
struct FullscreenPipeline {
    const char* fragment = nullptr;  // shader path under the shader root
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    const char* name = "";
};
ShaderStages compile_fullscreen(shader::Compiler& compiler, const char* fragment);
vk::Pipeline create_fullscreen(vk::Context& context, const FullscreenPipeline& pipeline,
                               const ShaderStages& stages, const graph::RenderTarget& target);

// Declares `target` the depth attachment of a fullscreen triangle whose fragment shader writes
// gl_FragDepth into every pixel (nothing loaded): depth_resolve, zfight_bound.
void declare_fullscreen_depth(graph::PassBuilder& b, graph::ImageHandle target);
// Records that triangle (test ALWAYS, writes on) with `sets` bound from set 0 and `push`.
void draw_fullscreen_depth(VkCommandBuffer cmd, VkPipeline pipeline, VkPipelineLayout layout,
                           std::span<const VkDescriptorSet> sets, std::span<const std::byte> push);

// Drawing over forward's HDR image against the scene depth, read-only (decals, transparent).
// msaa: into res.msaa_hdr against res.msaa_depth; with `resolve` the rendering ends by
// resolving it (AVERAGE) into res.hdr, which declare_hdr_over_depth then creates.
void declare_hdr_over_depth(graph::PassBuilder& b, FrameResources& res, bool msaa, bool resolve);

// A read-back compute pass's one descriptor set (msaa_probe, msaa_samples): `samplers`
// combined image samplers at bindings 0.., a storage buffer after them, and a pipeline layout
// with a compute push-constant range of `push_size` bytes.
struct ReadbackSet {
    vk::DescriptorSetLayout set_layout;
    vk::DescriptorPool pool;
    VkDescriptorSet set = VK_NULL_HANDLE;
    vk::PipelineLayout layout;
};
ReadbackSet make_readback_set(vk::Context& context, uint32_t samplers, uint32_t push_size,
                              const std::string& name);

// Why a pass that needs the prepass's depth and normals (gtao and its filters, contact
// shadows) is not in the frame: "<knob>=off", or "prepass off" / the subpass path's reason
// when the knob is on.
std::string off_or_without_prepass(bool on, const FrameOptions& options, const char* knob);
// Why a pass is not in a render_path=subpass frame.
std::string subpass_path_reason();

// The resolve mode that keeps the nearest depth (reverse-Z: MAX, else MIN) when `report`
// offers it and the frame resolves inline; NONE otherwise (then the depth_resolve pass
// resolves in a shader): render_path=subpass plans no depth resolve in its render pass.
VkResolveModeFlagBits native_depth_resolve(const vk::DeviceReport& report, const FrameOptions& o);
// What the report says: "native-max", "native-min" or "shader".
const char* depth_resolve_name(const vk::DeviceReport& report, const FrameOptions& o);

// Count images (shaders/common/count.glsl, set 3): R32_UINT, one per counting pass.
inline constexpr VkFormat kCountFormat = VK_FORMAT_R32_UINT;
inline constexpr uint32_t kCountSet = 3;
// A pool for one count set per frame (the buffer: count_draws' per-draw counters).
inline constexpr VkDescriptorPoolSize kCountPoolSizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 3},
                                                           {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
vk::DescriptorSetLayout create_count_set_layout(vk::Context& context);
// A counting pipeline's defines on this device: COUNT_FRAGMENTS=1, COUNT_QUADS=1 where it has
// quad subgroup operations in fragment shaders (fragment stage), and with `per_draw`
// (count_draws) COUNT_DRAWS=1 in both stages.
void add_count_defines(std::vector<shader::Define>& frag, std::vector<shader::Define>& vert,
                       const vk::Context& context, bool per_draw);
// Every valid count image of the frame's counting passes (clear_counts, readback_counts).
std::vector<graph::ImageHandle> count_images(const FrameResources& res);
// Declares what the counting fragment shader does to `counts` (clear_counts zeroed them).
void declare_counts(graph::PassBuilder& builder, const CountImages& counts);
// Set 3: binding 0 the shaded counts, binding 1 the discarded ones, binding 2 (count_draws
// only; left unwritten otherwise, and no shader without COUNT_DRAWS declares it) the shaded
// fragments per draw group, binding 3 the quads (devices that count them).
void write_count_set(const graph::PassContext& ctx, VkDevice device, VkDescriptorSet set,
                     const CountImages& counts);
// The pass's shaded, discarded, rasterized and quad totals from its read-back count images
// (none uncounted), and with count_draws its shaded fragments per draw group.
void collect_counts(const HostReadback& readback, const CountImages& counts, PassResult& out);

}  // namespace ds::passes
