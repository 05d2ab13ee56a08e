#pragma once
// What the screen-space compute passes (gtao, ao_spatial, ao_temporal, contact_shadows) share:
// one compute pipeline over [set 0 = the frame set, set 1 = the pass's images] plus push
// constants; a ring of set-1 descriptor sets, one per frame in flight (or several, for a pass
// that dispatches more than once a frame), rewritten every frame (the graph's image views
// change on resize); a sampler; an 8x8-group 2D dispatch.
// Plumbing, not a pass: passes include it, never each other.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/frame.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

// One binding of set 1, in binding order.
enum class KernelBinding : uint8_t {
    Sampled,  // combined image sampler, nearest, clamp to edge (the shaders use texelFetch)
    Storage,  // storage image (imageStore)
};

// The image behind one binding this frame, in the layout the graph gives it during the pass.
struct BoundImage {
    VkImageView view = VK_NULL_HANDLE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
};

class ComputeKernel {
  public:
    static constexpr uint32_t kGroupSize = 8;  // local_size_x/y of every screen-space shader

    // `shader` relative to the shader root. No pipeline until rebuild(). `dispatches`: how
    // many times a frame may dispatch it (each needs a set of its own).
    ComputeKernel(const PassServices& services, std::string shader,
                  std::vector<KernelBinding> bindings, uint32_t push_constant_size,
                  uint32_t dispatches = 1);

    // Fail-safe: compiles first (throws shader::ShaderError) and creates the pipeline (throws
    // ds::Error); only then is the current one replaced, going to `retired` since a frame in
    // flight may still use it. On any throw the current pipeline stays.
    void rebuild(vk::DestroyList& retired, const std::vector<shader::Define>& defines = {}) {
        install(prepare(defines), retired);
    }
    // The two halves, for a pass with several kernels: prepare all, then install all.
    struct Prepared {
        vk::Pipeline pipeline;
    };
    Prepared prepare(const std::vector<shader::Define>& defines = {}) const;
    void install(Prepared prepared, vk::DestroyList& retired);

    // Rewrites the ring's set for `frame_number` (its `slot`-th dispatch this frame, below
    // `dispatches`) with `images` (one per binding) and records bind, push constants and a
    // dispatch covering `extent`.
    void dispatch(VkCommandBuffer cmd, VkDescriptorSet frame_set, uint64_t frame_number,
                  std::span<const BoundImage> images, const void* push_constants, VkExtent2D extent,
                  uint32_t slot = 0);

    bool ready() const { return bool(pipeline_); }
    const std::string& shader() const { return shader_; }

  private:
    void write_set(VkDescriptorSet set, std::span<const BoundImage> images) const;

    vk::Context& context_;
    shader::Compiler& compiler_;
    std::string shader_;
    std::vector<KernelBinding> bindings_;
    uint32_t push_constant_size_;
    vk::Sampler nearest_;
    vk::DescriptorSetLayout set_layout_;
    vk::DescriptorPool pool_;
    uint32_t dispatches_;
    std::vector<VkDescriptorSet> sets_;  // kFramesInFlight x dispatches_, by frame then slot
    vk::PipelineLayout layout_;
    vk::Pipeline pipeline_;
};

// A compute pass that reads the prepass depth and normals (and the frame uniforms) and writes
// one new image `image` of `desc` with `kernel` (bindings: depth, normals, output). Returns
// the new image. gtao and contact_shadows are both this shape.
graph::ImageHandle add_depth_normals_pass(graph::RenderGraph& graph, const char* pass_name,
                                          const char* image_name, const graph::ImageDesc& desc,
                                          ComputeKernel& kernel, const void* push_constants,
                                          const FrameInputs& in, const FrameResources& res);

// One compute pipeline over a caller's layout, built on first use (a pass most frames leave
// out costs nothing) and rebuilt fail-safe (a shader error keeps the current one).
class LazyComputePipeline {
  public:
    LazyComputePipeline(const PassServices& services, std::string shader, const char* name,
                        std::vector<shader::Define> defines = {})
        : services_(services),
          shader_(std::move(shader)),
          name_(name),
          defines_(std::move(defines)) {}

    VkPipeline get(VkPipelineLayout layout);  // throws shader::ShaderError / ds::Error
    void rebuild(vk::DestroyList& retired);   // only if built

  private:
    void build(vk::DestroyList& retired);

    PassServices services_;
    std::string shader_;
    const char* name_;
    std::vector<shader::Define> defines_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    vk::Pipeline pipeline_;
};

// Group count covering `extent` with kGroupSize x kGroupSize groups.
inline uint32_t group_count(uint32_t pixels) {
    return (pixels + ComputeKernel::kGroupSize - 1) / ComputeKernel::kGroupSize;
}

}  // namespace ds::passes
