#include "renderer/renderer.h"

#include <algorithm>
#include <array>
#include <chrono>

#include "renderer/common/error.h"
#include "renderer/frame_targets.h"
#include "renderer/frame_uniforms.h"
#include "renderer/gpu_scene.h"
#include "renderer/graph/access.h"
#include "renderer/graph/graph.h"
#include "renderer/msaa_probe.h"
#include "renderer/passes/ao_spatial.h"
#include "renderer/passes/ao_temporal.h"
#include "renderer/passes/contact_shadows.h"
#include "renderer/passes/depth_prepass.h"
#include "renderer/passes/depth_resolve.h"
#include "renderer/passes/forward.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/gtao.h"
#include "renderer/passes/shadow.h"
#include "renderer/passes/skybox.h"
#include "renderer/passes/tonemap.h"
#include "renderer/passes/transparent.h"
#include "renderer/resource_inspector.h"
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

// The passes of the seed frame, in execution order (seed 000's, with transparent added).
struct Passes {
    passes::ShadowPass shadow;
    passes::DepthPrepass prepass;
    passes::GtaoPass gtao;
    passes::AoSpatialPass ao_spatial;
    passes::AoTemporalPass ao_temporal;
    passes::ContactShadowsPass contact_shadows;
    passes::ForwardPass forward;
    passes::SkyboxPass skybox;
    passes::TransparentPass transparent;
    passes::TonemapPass tonemap;

    explicit Passes(const passes::PassServices& s)
        : shadow(s),
          prepass(s),
          gtao(s),
          ao_spatial(s),
          ao_temporal(s),
          contact_shadows(s),
          forward(s),
          skybox(s),
          transparent(s),
          tonemap(s) {}

    // Fail-safe per pass: a shader error stops here and leaves the later passes as they were.
    void rebuild(vk::DestroyList& retired) {
        shadow.rebuild_pipelines(retired);
        prepass.rebuild_pipelines(retired);
        gtao.rebuild_pipelines(retired);
        ao_spatial.rebuild_pipelines(retired);
        ao_temporal.rebuild_pipelines(retired);
        contact_shadows.rebuild_pipelines(retired);
        forward.rebuild_pipelines(retired);
        skybox.rebuild_pipelines(retired);
        transparent.rebuild_pipelines(retired);
        tonemap.rebuild_pipelines(retired);
    }
};

// Why a pass is not in this frame's graph (the report lists it).
std::vector<std::string> skipped_passes(const passes::FrameOptions& o, const Settings& s) {
    std::vector<std::string> out;
    auto skip = [&](const char* pass, const std::string& why) {
        out.push_back(std::string(pass) + ": skipped (" + why + ")");
    };
    if (!o.shadows) skip("shadow", "shadows=off");
    if (!o.prepass) skip("depth_prepass", "prepass=off");
    // Switched off, or without the prepass depth and normals they read.
    auto why = [&](const char* knob) {
        return s.get_bool(knob) ? std::string("prepass off") : std::string(knob) + "=off";
    };
    if (!o.gtao)
        for (const char* p : {"gtao", "ao_spatial", "ao_temporal"}) skip(p, why("gtao"));
    if (!o.contact_shadows) skip("contact_shadows", why("contact_shadows"));
    if (!o.sky) skip("skybox", "sky=off");
    return out;
}

// msaa must be a count the device renders colour and depth with; the registry cannot know.
void check_samples(const vk::DeviceReport& report, VkSampleCountFlagBits samples) {
    const VkSampleCountFlags supported = report.color_sample_counts & report.depth_sample_counts;
    if (supported & samples) return;
    throw Error("msaa=" + std::to_string(int(samples)) + ": " + report.candidate.name +
                " supports sample counts " + vk::sample_counts_text(supported));
}

constexpr const char* kFinalImageName = "final";

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
                          .lifetime = r.lifetime,
                          .bytes = r.size};
        if (!r.is_image) s.format = VK_FORMAT_UNDEFINED;
        out.push_back(std::move(s));
    }
    return out;
}

// Fills each pass's reads and writes (by resource name) from the graph's declarations.
void add_declarations(const graph::RenderGraph& graph, std::vector<PassResult>& passes) {
    const auto resources = graph.resources();
    for (const graph::PassInfo& info : graph.passes()) {
        auto it = std::find_if(passes.begin(), passes.end(),
                               [&](const PassResult& p) { return p.name == info.name; });
        if (it == passes.end()) continue;
        for (const graph::AccessInfo& a : info.accesses) {
            std::vector<std::string>& list = graph::is_write(a.access) ? it->writes : it->reads;
            const std::string& name = resources[a.resource].name;
            if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
        }
    }
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

    explicit Impl(const RendererOptions& options);
    ~Impl();
    passes::FrameResources build_graph(const passes::FrameInputs& in, Slot& slot);
    void write_uniforms(Slot& slot, const scene::Camera& camera, const Settings& settings,
                        const passes::FrameInputs& in, const passes::FrameResources& res);
    void collect(Slot& slot, uint64_t graph_frame, const passes::FrameOptions& options,
                 ReadBack read_back, FrameResult& result);

    // Declared in creation order; ~Impl tears down explicitly in reverse.
    std::unique_ptr<vk::Context> context;
    std::unique_ptr<shader::Compiler> compiler;
    vk::DescriptorSetLayout frame_layout;
    vk::DescriptorSetLayout material_layout;
    vk::DescriptorPool frame_pool;
    std::array<Slot, vk::FrameRing::kFramesInFlight> slots;
    std::unique_ptr<vk::FrameRing> frames;
    std::unique_ptr<graph::RenderGraph> graph;
    std::unique_ptr<Passes> passes;
    std::unique_ptr<FrameTargets> targets;
    std::unique_ptr<GpuScene> scene;
    std::unique_ptr<MsaaProbe> probe;              // created by the first msaa > 1 frame
    std::unique_ptr<ResourceInspector> inspector;  // pipelines built by the first request
    scene::DirectionalLight sun;
    scene::Bounds scene_bounds;
    // Temporal state: last frame's view-projection, unless the next frame is a cut.
    glm::mat4 previous_view_projection{1.0f};
    bool cut = true;
    VkExtent2D last_size{0, 0};  // a new size is a cut: last frame's pixels do not map
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
    const VkFormat depth_format = context->report().depth_format;
    const passes::PassServices services{*context, *compiler, frame_layout.handle(),
                                        material_layout.handle(), depth_format};
    passes = std::make_unique<Passes>(services);
    inspector = std::make_unique<ResourceInspector>(services);
    targets = std::make_unique<FrameTargets>(*context, passes::TonemapPass::kFinalFormat,
                                             depth_format, passes::ForwardPass::kHdrFormat);
}

Renderer::Impl::~Impl() {
    if (!context) return;
    vkDeviceWaitIdle(context->device());  // teardown: an error here has nowhere to go
    if (targets) targets->reset();
    inspector.reset();
    probe.reset();
    scene.reset();
    frames.reset();  // flushes every destroy list
    passes.reset();
    graph.reset();
    targets.reset();
    for (Slot& slot : slots) slot = Slot{};
    frame_pool = vk::DescriptorPool{};
    material_layout.reset();
    frame_layout.reset();
    compiler.reset();
    context.reset();  // device, messenger, instance last
}

passes::FrameResources Renderer::Impl::build_graph(const passes::FrameInputs& in, Slot& slot) {
    passes::FrameResources res;
    graph::ExternalBuffer uniforms;
    uniforms.buffer = slot.uniforms.handle();
    uniforms.size = slot.uniforms.size();
    uniforms.initial = {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_HOST_BIT,
                        VK_ACCESS_2_HOST_WRITE_BIT};  // written before the submit
    res.frame_uniforms = graph->import_buffer("frame_uniforms", uniforms);
    targets->import(*graph, in.options, res);

    Passes& p = *passes;
    if (in.options.shadows) p.shadow.add(*graph, in, res);
    if (in.options.prepass) p.prepass.add(*graph, in, res);
    // The screen-space passes decide themselves from the options and what exists: gtao and
    // contact shadows need the prepass (FrameOptions folds that in); the AO filters need gtao.
    p.gtao.add(*graph, in, res);
    p.ao_spatial.add(*graph, in, res);
    p.ao_temporal.add(*graph, in, res);
    p.contact_shadows.add(*graph, in, res);
    p.forward.add(*graph, in, res);
    if (in.options.sky) p.skybox.add(*graph, in, res);
    p.transparent.add(*graph, in, res);
    p.tonemap.add(*graph, in, res);
    return res;
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

void Renderer::Impl::collect(Slot& slot, uint64_t graph_frame, const passes::FrameOptions& options,
                             ReadBack read_back, FrameResult& result) {
    for (const graph::PassResult& g : graph->collect(graph_frame)) {
        PassResult p;
        p.name = g.name;
        p.gpu_ms = g.gpu_ms;
        p.vertex_shader_invocations = g.vertex_invocations;
        p.fragment_shader_invocations = g.fragment_invocations;
        p.clipping_primitives = g.clipping_primitives;
        if (p.name == passes::DepthPrepass::kName)
            p.shaded_fragments = targets->count_sum(CountImage::Prepass);
        else if (p.name == passes::ForwardPass::kName)
            p.shaded_fragments = targets->count_sum(CountImage::Forward);
        else if (p.name == passes::TransparentPass::kName)
            p.shaded_fragments = targets->count_sum(CountImage::Transparent);
        result.passes.push_back(std::move(p));
    }
    if (slot.timestamps.count()) {
        if (auto ticks = slot.timestamps.results())
            result.gpu_ms = slot.timestamps.ticks_to_ms((*ticks)[0], (*ticks)[1]);
    }
    const bool full = read_back == ReadBack::Yes || read_back == ReadBack::WithMsaaDepth;
    if (full || options.count_fragments)
        result.covered_pixels = targets->covered_pixels(options.far_depth());
    if (read_back != ReadBack::No) result.rgba8 = targets->rgba8();
    result.msaa.samples = uint32_t(options.samples);
    if (!options.msaa()) return;
    result.msaa.depth_resolve = passes::depth_resolve_name(context->report(), options.reverse_z);
    if (!full) return;
    result.msaa.edge_pixels = probe->edge_pixels();
    if (read_back == ReadBack::WithMsaaDepth) {
        result.msaa.depth_samples = probe->depth_samples();
        result.msaa.resolved_depth = targets->depth_floats();
        if (result.msaa.resolved_depth.empty()) result.msaa.depth_samples.clear();
    }
}

Renderer::Renderer(const RendererOptions& options) : impl_(std::make_unique<Impl>(options)) {}

Renderer::~Renderer() = default;

const vk::DeviceReport& Renderer::device_report() const {
    return impl_->context->report();
}

std::string Renderer::graph_dump() const {
    return impl_->graph->dump();
}

uint64_t Renderer::validation_message_count() const {
    return impl_->context->validation_message_count();
}

VkInstance Renderer::instance() const {
    return impl_->context->instance();
}

void Renderer::camera_cut() {
    impl_->cut = true;
}

void Renderer::rebuild_pipelines() {
    impl_->passes->rebuild(impl_->frames->retire_list());
    if (impl_->inspector) impl_->inspector->rebuild_pipelines(impl_->frames->retire_list());
}

vk::Context& Renderer::context() {
    return *impl_->context;
}

void Renderer::set_scene(const scene::Scene& scene) {
    Impl& r = *impl_;
    // Descriptor sets that in-flight frames use are rewritten below: let them finish first.
    r.context->wait_idle();
    r.scene.reset();
    r.scene = std::make_unique<GpuScene>(*r.context, scene, r.material_layout.handle());
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

FrameResult Renderer::render(const scene::Camera& camera, const Settings& settings, uint32_t width,
                             uint32_t height, ReadBack read_back, const InspectRequest& inspect) {
    Impl& r = *impl_;
    if (!r.scene) throw Error("render: no scene (call set_scene first)");
    if (width == 0 || height == 0)
        throw Error("render: size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is empty");
    const passes::FrameOptions options = passes::FrameOptions::from(settings);
    if (options.count_fragments && !r.context->report().fragment_stores_and_atomics)
        throw Error("count_fragments=on needs fragmentStoresAndAtomics, which " +
                    r.context->report().candidate.name + " does not offer");
    check_samples(r.context->report(), options.samples);
    if (options.sample_shading && !r.context->report().sample_rate_shading)
        throw Error("sample_shading=on needs sampleRateShading, which " +
                    r.context->report().candidate.name + " does not offer");
    // material_alpha_cutoff: checked against the scene (an unknown name throws) and uploaded
    // when it changed, before this frame begins.
    r.scene->set_alpha_cutoff_overrides(settings.get_map("material_alpha_cutoff"));
    if (options.msaa() && !r.probe) r.probe = std::make_unique<MsaaProbe>(*r.context, *r.compiler);
    const auto start = std::chrono::steady_clock::now();
    vk::Frame& frame = r.frames->begin();
    Impl::Slot& slot = r.slots[frame.number % vk::FrameRing::kFramesInFlight];
    const VkExtent2D size{width, height};
    if (size.width != r.last_size.width || size.height != r.last_size.height) r.cut = true;
    r.last_size = size;
    r.targets->ensure(size, options.count_fragments, options.samples, frame.retired);
    if (r.cut) r.graph->invalidate_history();
    r.graph->begin_frame(size, frame.retired);  // a new size invalidates history too

    const passes::FrameInputs in{.scene = r.scene.get(),
                                 .frame_set = slot.set,
                                 .options = options,
                                 .camera_position = camera.position,
                                 .frame_number = frame.number};
    const passes::FrameResources res = r.build_graph(in, slot);
    // "final" is read back as it is (sRGB-encoded); any other image through the inspect pass.
    const bool inspect_final = inspect.resource == kFinalImageName;
    if (inspect_final && read_back == ReadBack::No) read_back = ReadBack::Color;
    const std::vector<ResourceSummary> resources = summarize(*r.graph);
    bool inspecting = false;
    if (!inspect.resource.empty() && !inspect_final) {
        inspecting =
            r.inspector->add(*r.graph, in, inspect.resource, inspect.sample, frame.retired);
    }
    r.write_uniforms(slot, camera, settings, in, res);
    r.graph->compile();

    VkCommandBuffer cmd = frame.cmd;
    if (slot.timestamps.count()) {
        slot.timestamps.reset(cmd);
        slot.timestamps.write(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, 0);
    }
    const uint64_t graph_frame = r.graph->execute(cmd);
    if (slot.timestamps.count())
        slot.timestamps.write(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, 1);
    const bool full = read_back == ReadBack::Yes || read_back == ReadBack::WithMsaaDepth;
    r.targets->record_read_back(cmd, read_back != ReadBack::No, full || options.count_fragments);
    if (inspecting) r.inspector->record_read_back(cmd);
    // The exact edge count reads every sample: only frames that are read back pay for it.
    if (options.msaa() && full)
        r.probe->record(cmd, r.targets->msaa_depth(), r.targets->msaa_hdr(),
                        read_back == ReadBack::WithMsaaDepth);
    r.frames->submit(frame);

    FrameResult result;
    result.width = width;
    result.height = height;
    result.cpu_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    result.skipped = skipped_passes(options, settings);
    r.frames->wait(frame);
    r.collect(slot, graph_frame, options, read_back, result);
    if (const auto counts = r.passes->prepass.discard_counts(frame.number))
        result.masked_discards = DiscardCounts{counts->invoked, counts->discarded};
    add_declarations(*r.graph, result.passes);
    result.resources = resources;
    if (inspecting) result.inspected = r.inspector->result();
    if (inspect_final) result.inspected = final_as_inspected(result);
    if (result.inspected) {
        result.inspected->znear = camera.znear;
        result.inspected->zfar = camera.zfar;
        result.inspected->reverse_z = options.reverse_z;
    }
    return result;
}

}  // namespace ds
