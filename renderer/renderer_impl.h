#pragma once
// Renderer's private state (renderer.h's pimpl), shared by renderer.cpp (creation, scenes, the
// public queries) and renderer_frame.cpp (one frame: options, graph, record, collect).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/frame/frame_memory.h"
#include "renderer/frame/frame_targets.h"
#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/readback/host_readback.h"
#include "renderer/renderer.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/context.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/frame.h"
#include "renderer/vk/query.h"

namespace ds {

enum FrameBinding : uint32_t { kFrameUniforms = 0, kInstances = 1 };

struct Renderer::Impl {
    struct Slot {  // per frame in flight
        vk::Buffer uniforms;
        VkDescriptorSet set = VK_NULL_HANDLE;
        vk::TimestampPool timestamps;  // around the whole graph
    };
    // A frame pass and the graph passes it added this frame, [first, last).
    struct Added {
        passes::FramePass* pass = nullptr;
        size_t first = 0, last = 0;
    };

    explicit Impl(const RendererOptions& options);
    ~Impl();
    passes::FrameOptions options_for(const Settings& settings, const RenderRequest& request);
    FrameShape shape(VkExtent2D size, const passes::FrameOptions& options) const;
    void check_memory(const FrameMemory& frame, const FrameShape& shape) const;
    void begin(VkExtent2D size, vk::Frame& frame);
    uint64_t record(Slot& slot, VkCommandBuffer cmd);
    passes::FrameResources build_graph(const passes::FrameInputs& in, Slot& slot,
                                       vk::DestroyList& retired);
    std::vector<std::string> skipped() const;
    void write_uniforms(Slot& slot, const scene::Camera& camera, const Settings& settings,
                        const passes::FrameInputs& in, const passes::FrameResources& res);
    void collect(Slot& slot, uint64_t graph_frame, const passes::FrameInputs& in,
                 const passes::FrameResources& res, FrameResult& result);

    // Declared in creation order; ~Impl tears down explicitly in reverse.
    std::unique_ptr<vk::Context> context;
    std::unique_ptr<shader::Compiler> compiler;
    vk::DescriptorSetLayout frame_layout;
    vk::DescriptorSetLayout material_layout;
    vk::DescriptorPool frame_pool;
    std::array<Slot, vk::FrameRing::kFramesInFlight> slots;
    std::unique_ptr<vk::FrameRing> frames;
    std::unique_ptr<graph::RenderGraph> graph;
    std::unique_ptr<HostReadback> readback;
    std::vector<std::unique_ptr<passes::FramePass>> passes;  // the frame, in order
    std::vector<Added> added;                                // this frame's
    std::vector<ResourceSummary> resources;                  // this frame's, before read-back
    std::unique_ptr<FrameTargets> targets;
    std::unique_ptr<GpuScene> scene;
    uint64_t scene_bytes = 0;  // device memory set_scene() allocated (the memory check's share)
    scene::DirectionalLight sun;
    scene::Bounds scene_bounds;
    // Temporal state: last frame's view-projection, unless the next frame is a cut.
    glm::mat4 previous_view_projection{1.0f};
    bool cut = true;
    VkExtent2D last_size{0, 0};  // a new size is a cut: last frame's pixels do not map
    VkSampleCountFlagBits last_samples = VK_SAMPLE_COUNT_1_BIT;
};

}  // namespace ds
