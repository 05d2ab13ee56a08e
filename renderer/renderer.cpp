#include "renderer/renderer.h"
#include "renderer/renderer_impl.h"

#include <algorithm>
#include <array>
#include <chrono>

#include <nlohmann/json.hpp>

#include "renderer/common/error.h"
#include "renderer/frame/frame_memory.h"
#include "renderer/frame/frame_passes.h"
#include "renderer/frame/frame_targets.h"
#include "renderer/frame/frame_uniforms.h"
#include "renderer/frame/tiler_summary.h"
#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/graph/access.h"
#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/msaa_samples.h"
#include "renderer/passes/pass_util.h"
#include "renderer/passes/pixel_history.h"
#include "renderer/readback/host_readback.h"
#include "renderer/settings/frame_knobs.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/context.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/frame.h"
#include "renderer/vk/pipeline.h"
#include "renderer/vk/query.h"

namespace ds {

Renderer::Impl::Impl(const RendererOptions& options) {
    context = std::make_unique<vk::Context>(
        vk::ContextOptions{.validate = options.validate,
                           .device = options.device,
                           .instance_extensions = options.instance_extensions,
                           .swapchain = options.swapchain});
    compiler = std::make_unique<shader::Compiler>();
    // The frame uniforms are read by every stage (the screen-space passes are compute).
    const VkDescriptorSetLayoutBinding frame_bindings[] = {
        vk::layout_binding(kFrameUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                           VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT |
                               VK_SHADER_STAGE_COMPUTE_BIT),
        vk::layout_binding(kInstances, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           VK_SHADER_STAGE_VERTEX_BIT)};
    frame_layout = vk::DescriptorSetLayout(*context, frame_bindings, "frame set layout");
    material_layout = create_material_set_layout(*context);

    const uint32_t n = vk::FrameRing::kFramesInFlight;
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, n},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, n}};
    frame_pool = vk::DescriptorPool(*context, n, sizes, "frame sets");
    const bool timestamps = context->report().timestamps && context->report().timestamp_valid_bits;
    for (Slot& slot : slots) {
        slot.uniforms =
            vk::Buffer(*context, {sizeof(passes::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                  vk::MemoryUsage::Upload, "frame uniforms"});
        slot.set = frame_pool.allocate(frame_layout.handle());
        if (timestamps) slot.timestamps = vk::TimestampPool(*context, 2);
    }
    frames = std::make_unique<vk::FrameRing>(*context);
    graph = std::make_unique<graph::RenderGraph>(*context);
    readback = std::make_unique<HostReadback>(*context);
    const passes::PassServices services{*context,
                                        *compiler,
                                        frame_layout.handle(),
                                        material_layout.handle(),
                                        context->report().depth_format,
                                        *readback};
    passes = make_frame_passes(services);
    targets = std::make_unique<FrameTargets>(*context, passes::kFinalFormat, passes::kHdrFormat);
}

Renderer::Impl::~Impl() {
    if (!context) return;
    context->drain();
    if (targets) targets->reset();
    scene.reset();
    frames.reset();  // flushes every destroy list
    passes.clear();
    if (readback) readback->reset();
    readback.reset();
    graph.reset();
    targets.reset();
    for (Slot& slot : slots) slot = Slot{};
    frame_pool = vk::DescriptorPool{};
    material_layout.reset();
    frame_layout.reset();
    compiler.reset();
    context.reset();  // device, messenger, instance last
}

// The frame declared, its memory estimate checked, then the targets made for it: a refused
// frame is never submitted, and the next begin_frame() starts over.
Renderer::Renderer(const RendererOptions& options)
    : impl_(std::make_unique<Impl>(options)), validation_(impl_->context->validation_counter()) {}

void Renderer::shutdown() {
    impl_.reset();
}

Renderer::Impl& Renderer::live() const {
    if (!impl_) throw Error("renderer: used after shutdown()");
    return *impl_;
}

Renderer::~Renderer() = default;

const vk::DeviceReport& Renderer::device_report() const {
    return live().context->report();
}

std::string Renderer::graph_dump() const {
    return live().graph->dump();
}

nlohmann::json Renderer::graph_json() const {
    return live().graph->dump_json();
}

std::optional<SurfaceInfo> Renderer::describe_surface(uint32_t id) const {
    const Impl& r = live();
    if (!r.scene) return std::nullopt;
    const SurfaceTable& table = r.scene->surfaces();
    const std::optional<SurfaceRef> ref = table.find(id);
    if (!ref) return std::nullopt;
    return SurfaceInfo{table.name(ref->instance), ref->instance, ref->triangle};
}

uint64_t Renderer::validation_message_count() const {
    return validation_->load();
}

VkInstance Renderer::instance() const {
    return live().context->instance();
}

void Renderer::camera_cut() {
    live().cut = true;
}

// Fail-safe per pass: a shader error stops here and leaves the later passes as they were.
void Renderer::rebuild_pipelines() {
    Impl& r = live();
    for (const std::unique_ptr<passes::FramePass>& pass : r.passes)
        pass->rebuild_pipelines(r.frames->retire_list());
}

vk::Context& Renderer::context() {
    return *live().context;
}

void Renderer::set_scene(const scene::Scene& scene) {
    Impl& r = live();
    // Descriptor sets that in-flight frames use are rewritten below: let them finish first.
    r.context->wait_idle();
    r.scene.reset();
    const uint64_t before = r.context->allocator().stats().used_bytes;
    r.scene = std::make_unique<GpuScene>(*r.context, scene, r.material_layout.handle());
    r.scene_bytes = r.context->allocator().stats().used_bytes - before;
    r.sun = scene.sun;
    r.scene_bounds = scene.bounds;
    r.cut = true;
    for (Impl::Slot& slot : r.slots) {
        vk::DescriptorWriter writer;
        writer.buffer(kFrameUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, slot.uniforms.handle())
            .buffer(kInstances, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, r.scene->instance_buffer());
        writer.update(r.context->device(), slot.set);
    }
}

// The settings as this frame's options, checked against the device and the scene: the
// frame-wide knobs, then every pass's own (configure, in list order), then the providers'
// decisions on what others asked of them (resolve). Passes hear of a new sample count before
// the frame is declared.
}  // namespace ds
