#include "renderer/renderer.h"

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
namespace {

enum FrameBinding : uint32_t { kFrameUniforms = 0, kInstances = 1 };

// What the settings ask of the device that the registry cannot know; the depth_format choice
// becomes the device's format for it here.
void check_device(const vk::DeviceReport& report, passes::FrameOptions& options) {
    options.depth_format = passes::resolve_depth_format(options.depth_choice, report.depth_formats,
                                                        report.candidate.name);
    const VkSampleCountFlags supported = report.color_sample_counts & report.depth_sample_counts;
    if (!(supported & options.samples))
        throw Error("msaa=" + std::to_string(int(options.samples)) + ": " + report.candidate.name +
                    " supports sample counts " + vk::sample_counts_text(supported));
    if (options.sample_shading && !report.sample_rate_shading)
        throw Error("sample_shading=on needs sampleRateShading, which " + report.candidate.name +
                    " does not offer");
}

constexpr const char* kFinalImageName = "final";

// The sample view's rectangle: it starts inside the frame (the pass clamps its far corner), is
// not empty and not larger than the pass reads.
void check_sample_query(const std::optional<SampleQuery>& q, uint32_t width, uint32_t height) {
    if (!q) return;
    const std::string rect = std::to_string(q->x) + "," + std::to_string(q->y) + " " +
                             std::to_string(q->width) + "x" + std::to_string(q->height);
    if (q->x >= width || q->y >= height || q->width == 0 || q->height == 0)
        throw Error("render: sample rectangle " + rect + " is empty or outside the frame (" +
                    std::to_string(width) + "x" + std::to_string(height) + ")");
    if (uint64_t(q->width) * q->height > passes::MsaaSamplesPass::kMaxPixels)
        throw Error("render: sample rectangle " + rect + " has more than " +
                    std::to_string(passes::MsaaSamplesPass::kMaxPixels) + " pixels");
}

std::vector<ResourceSummary> summarize(const graph::RenderGraph& graph) {
    std::vector<ResourceSummary> out;
    for (const graph::ResourceInfo& r : graph.resources()) {
        ResourceSummary s{.name = r.name,
                          .is_image = r.is_image,
                          .format = r.image.format,
                          .width = r.extent.width,
                          .height = r.extent.height,
                          .samples = uint32_t(r.image.samples),
                          .semantic = r.image.semantic,
                          .display = r.image.display,
                          .lifetime = r.lifetime,
                          .bytes = r.size};
        if (!r.is_image) s.format = VK_FORMAT_UNDEFINED;
        out.push_back(std::move(s));
    }
    return out;
}

// One graph pass's measurements, role and declarations (resource names, declaration order).
PassResult pass_result(const graph::PassResult& g, const graph::PassInfo& info,
                       std::span<const graph::ResourceInfo> resources) {
    PassResult p;
    p.name = g.name;
    p.role = info.role;
    p.subpass_group = info.group;
    p.subpass = info.subpass;
    p.gpu_ms = g.gpu_ms;
    p.gpu_start_ms = g.gpu_start_ms;
    p.vertex_shader_invocations = g.vertex_invocations;
    p.fragment_shader_invocations = g.fragment_invocations;
    p.clipping_primitives = g.clipping_primitives;
    for (const graph::AccessInfo& a : info.accesses) {
        std::vector<std::string>& list = graph::is_write(a.access) ? p.writes : p.reads;
        const std::string& name = resources[a.resource].name;
        if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
    }
    return p;
}

// The final image as the inspector sees any other: four floats per texel (sRGB-encoded).
InspectedImage final_as_inspected(const FrameResult& frame) {
    InspectedImage image;
    image.name = kFinalImageName;
    // Its bytes as stored (sRGB-encoded), which is what a UNORM view of them reads.
    image.format = VK_FORMAT_R8G8B8A8_UNORM;
    image.semantic = graph::Semantic::LdrColor;
    image.width = frame.width;
    image.height = frame.height;
    image.texels.resize(frame.rgba8.size());
    for (size_t i = 0; i < frame.rgba8.size(); ++i) image.texels[i] = frame.rgba8[i] / 255.0f;
    return image;
}

}  // namespace

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
    vkDeviceWaitIdle(context->device());  // teardown: an error here has nowhere to go
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
passes::FrameResources Renderer::Impl::build_graph(const passes::FrameInputs& in, Slot& slot,
                                                   vk::DestroyList& retired) {
    passes::FrameResources res;
    graph::ExternalBuffer uniforms;
    uniforms.buffer = slot.uniforms.handle();
    uniforms.size = slot.uniforms.size();
    uniforms.initial = {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_HOST_BIT,
                        VK_ACCESS_2_HOST_WRITE_BIT};  // written before the submit
    res.frame_uniforms = graph->import_buffer("frame_uniforms", uniforms);
    targets->import(*graph, in.options, res);
    added.clear();
    resources.clear();
    // render_path=subpass: the graph plans prepass, forward, sky, decals and transparent (the
    // run that shares the scene depth) as the subpasses of one render pass.
    if (in.options.subpass) graph->plan_subpasses(passes::kSubpassGroup);
    for (const std::unique_ptr<passes::FramePass>& pass : passes) {
        // The frame's resources, as the inspector lists them: read-back's own are plumbing.
        if (pass->role() == graph::PassRole::ReadBack && resources.empty())
            resources = summarize(*graph);
        const size_t first = graph->passes().size();
        pass->add(*graph, in, res);
        added.push_back({pass.get(), first, graph->passes().size()});
    }
    const VkExtent2D size = graph->output_extent();
    check_memory(frame_memory(graph->resources()), shape(size, in.options));
    targets->ensure(size, in.options, retired);
    targets->bind(*graph, res);
    return res;
}

// Why passes are not in this frame's graph ("gtao: skipped (prepass off)"), in pass order.
std::vector<std::string> Renderer::Impl::skipped() const {
    std::vector<std::string> out;
    for (const std::unique_ptr<passes::FramePass>& pass : passes)
        if (const auto& why = pass->skipped())
            out.push_back(std::string(pass->name()) + ": skipped (" + *why + ")");
    return out;
}

void Renderer::Impl::write_uniforms(Slot& slot, const scene::Camera& camera,
                                    const Settings& settings, const passes::FrameInputs& in,
                                    const passes::FrameResources& res) {
    uint32_t flags = 0;
    if (res.shadow_map.valid()) flags |= passes::kFrameShadows;
    if (res.ao.valid()) flags |= passes::kFrameAO;
    if (res.contact_shadows.valid()) flags |= passes::kFrameContactShadows;
    const VkExtent2D size = graph->output_extent();
    const passes::FrameUniforms u =
        frame_uniforms({.camera = camera,
                        .settings = settings,
                        .options = in.options,
                        .sun = sun,
                        .scene_bounds = scene_bounds,
                        .size = size,
                        .previous_view_projection = cut ? nullptr : &previous_view_projection,
                        .flags = flags,
                        .frame_number = in.frame_number});
    slot.uniforms.write(&u, sizeof u);
    previous_view_projection = u.view_projection;
    cut = false;
}

// After the fence: every graph pass's measurements, then each frame pass fills in its own
// results (matched by position: the graph passes it added) and the frame-level ones.
void Renderer::Impl::collect(Slot& slot, uint64_t graph_frame, const passes::FrameInputs& in,
                             const passes::FrameResources& res, FrameResult& result) {
    const std::vector<graph::PassResult> measured = graph->collect(graph_frame);
    const std::span<const graph::PassInfo> infos = graph->passes();
    for (size_t i = 0; i < measured.size(); ++i)
        result.passes.push_back(pass_result(measured[i], infos[i], graph->resources()));
    const passes::FrameCollect c{in, res, *readback};
    for (const Added& a : added) {
        const std::span<PassResult> own(result.passes.data() + a.first, a.last - a.first);
        a.pass->collect(c, own, result);
    }
    for (const FrameJoin join : frame_joins()) join(result);
    if (slot.timestamps.count()) {
        if (auto ticks = slot.timestamps.results())
            result.gpu_ms = slot.timestamps.ticks_to_ms((*ticks)[0], (*ticks)[1]);
    }
    result.tiler = tiler_summary(*graph);
    if (result.tiler)
        for (const std::unique_ptr<passes::FramePass>& pass : passes)
            for (const std::string& knob : pass->turned_off())
                result.subpass_turned_off.push_back(knob);
    result.msaa.samples = uint32_t(in.options.samples);
    if (in.options.msaa())
        result.msaa.depth_resolve = passes::depth_resolve_name(context->report(), in.options);
    // Depth samples only come with a resolved depth to compare them with (D32).
    if (result.msaa.resolved_depth.empty()) result.msaa.depth_samples.clear();
}

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
passes::FrameOptions Renderer::Impl::options_for(const Settings& settings,
                                                 const RenderRequest& request) {
    passes::FrameOptions options = passes::FrameOptions::from(settings);
    check_device(context->report(), options);
    const passes::FrameSetup setup{settings, *scene, context->report(), request};
    for (const std::unique_ptr<passes::FramePass>& pass : passes) {
        pass->clear_gate();
        pass->configure(setup, options);
    }
    for (const std::unique_ptr<passes::FramePass>& pass : passes) pass->resolve(options);
    // material_alpha_cutoff: checked against the scene (an unknown name throws) and uploaded
    // when it changed, before this frame begins.
    scene->set_alpha_cutoff_overrides(knob_value(settings, knobs::kMaterialAlphaCutoff));
    if (options.samples != last_samples)
        for (const std::unique_ptr<passes::FramePass>& pass : passes)
            pass->on_sample_count_changed(options.samples);
    last_samples = options.samples;
    return options;
}

FrameShape Renderer::Impl::shape(VkExtent2D size, const passes::FrameOptions& options) const {
    return {context->report().candidate.name, size, options.samples};
}

// The budget is asked for each time: VK_EXT_memory_budget's changes with other processes.
void Renderer::Impl::check_memory(const FrameMemory& frame, const FrameShape& shape) const {
    const vk::DeviceLimits& limits = context->report().limits;
    check_frame_memory(frame, scene_bytes, vk::heap_budget(context->physical_device(), limits),
                       limits, shape);
}

// Graph and read-back ready for a frame of `size` (a new size is a camera cut); the targets
// come once the declared frame's memory estimate passed.
void Renderer::Impl::begin(VkExtent2D size, vk::Frame& frame) {
    if (size.width != last_size.width || size.height != last_size.height) cut = true;
    last_size = size;
    if (cut) graph->invalidate_history();
    graph->begin_frame(size, frame.retired);  // a new size invalidates history too
    readback->begin_frame(frame.retired);
}

// The compiled graph into the frame's command buffer, bracketed by the frame's timestamps.
uint64_t Renderer::Impl::record(Slot& slot, VkCommandBuffer cmd) {
    if (slot.timestamps.count()) {
        slot.timestamps.reset(cmd);
        slot.timestamps.write(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, 0);
    }
    const uint64_t graph_frame = graph->execute(cmd);
    if (slot.timestamps.count())
        slot.timestamps.write(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, 1);
    return graph_frame;
}

FrameResult Renderer::render(const scene::Camera& scene_camera, const Settings& settings,
                             const RenderRequest& request) {
    Impl& r = live();
    if (!r.scene) throw Error("render: no scene (call set_scene first)");
    const uint32_t width = request.width, height = request.height;
    const std::optional<PixelQuery>& pixel = request.pixel;
    const std::vector<InspectRequest>& inspect = request.inspect;
    if (width == 0 || height == 0)
        throw Error("render: size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is empty");
    if (pixel && (pixel->x >= width || pixel->y >= height))
        throw Error("render: pixel " + std::to_string(pixel->x) + "," + std::to_string(pixel->y) +
                    " is outside the frame (" + std::to_string(width) + "x" +
                    std::to_string(height) + ")");
    check_sample_query(request.samples, width, height);
    const passes::FrameOptions options = r.options_for(settings, request);
    // The scene camera with the znear / zfar knobs, checked before the frame begins; the
    // frame uses only this one.
    const scene::Camera camera = passes::effective_camera(scene_camera, options);
    // "final" is read back as it is (sRGB-encoded); any other image through the inspect pass.
    const bool inspect_final = !inspect.empty() && inspect[0].resource == kFinalImageName;
    ReadBack read_back = request.read_back;
    if (inspect_final && read_back == ReadBack::No) read_back = ReadBack::Color;
    // Before anything is allocated: the size here, the frame's memory once it is declared.
    check_frame_size(r.context->report().limits, r.shape({width, height}, options));

    const auto start = std::chrono::steady_clock::now();
    vk::Frame& frame = r.frames->begin();
    Impl::Slot& slot = r.slots[frame.number % vk::FrameRing::kFramesInFlight];
    r.begin({width, height}, frame);
    const passes::FrameInputs in{.scene = r.scene.get(),
                                 .frame_set = slot.set,
                                 .options = options,
                                 .camera_position = camera.position,
                                 .frame_number = frame.number,
                                 .read_back = read_back,
                                 .inspect = inspect,
                                 .pixel = pixel,
                                 .samples = request.samples};
    const passes::FrameResources res = r.build_graph(in, slot, frame.retired);
    r.write_uniforms(slot, camera, settings, in, res);
    r.graph->compile();
    const uint64_t graph_frame = r.record(slot, frame.cmd);
    r.frames->submit(frame);

    FrameResult result;
    result.width = width;
    result.height = height;
    result.cpu_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    result.skipped = r.skipped();
    r.frames->wait(frame);
    r.collect(slot, graph_frame, in, res, result);
    result.resources = r.resources;
    // A pixel nothing covered still has a (empty) history.
    if (pixel && !result.find<PixelHistory>()) result.slots.put(PixelHistory{pixel->x, pixel->y});
    if (inspect_final) result.inspected = final_as_inspected(result);
    auto with_planes = [&](InspectedImage& image) {
        image.znear = camera.znear;
        image.zfar = camera.zfar;
        image.reverse_z = options.reverse_z;
    };
    if (result.inspected) with_planes(*result.inspected);
    for (InspectedImage& image : result.overlays) with_planes(image);
    // The scene depth as this frame used it (report.json's "depth").
    result.depth = DepthResult{.format = options.depth_format,
                               .znear = camera.znear,
                               .zfar = camera.zfar,
                               .reverse_z = options.reverse_z};
    return result;
}

}  // namespace ds
