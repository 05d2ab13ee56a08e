// Renderer, one frame: the frame's options, its graph, recording, collection (renderer.h).
#include "renderer/renderer_impl.h"

#include <algorithm>
#include <array>
#include <chrono>

#include <nlohmann/json.hpp>

#include "renderer/common/error.h"
#include "renderer/frame/alpha_coverage_report.h"
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
// The request's own sense: a size, a pixel inside it, a sample rectangle inside it.
void check_request(const RenderRequest& request) {
    const uint32_t width = request.width, height = request.height;
    const std::optional<PixelQuery>& pixel = request.pixel;
    if (width == 0 || height == 0)
        throw Error("render: size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is empty");
    if (pixel && (pixel->x >= width || pixel->y >= height))
        throw Error("render: pixel " + std::to_string(pixel->x) + "," + std::to_string(pixel->y) +
                    " is outside the frame (" + std::to_string(width) + "x" +
                    std::to_string(height) + ")");
    check_sample_query(request.samples, width, height);
}

InspectedImage final_as_inspected(const FrameResult& frame);

// What the frame's result says beyond its passes: a pixel nothing covered still has an (empty)
// history, inspected images carry the planes, and the scene depth as this frame used it
// (report.json's "depth").
void finish(FrameResult& result, const scene::Camera& camera, const passes::FrameOptions& options,
            const std::optional<PixelQuery>& pixel, bool inspect_final) {
    if (pixel && !result.find<PixelHistory>()) result.slots.put(PixelHistory{pixel->x, pixel->y});
    if (inspect_final) result.inspected = final_as_inspected(result);
    auto with_planes = [&](InspectedImage& image) {
        image.znear = camera.znear;
        image.zfar = camera.zfar;
        image.reverse_z = options.reverse_z;
    };
    if (result.inspected) with_planes(*result.inspected);
    for (InspectedImage& image : result.overlays) with_planes(image);
    result.depth = DepthResult{.format = options.depth_format,
                               .znear = camera.znear,
                               .zfar = camera.zfar,
                               .reverse_z = options.reverse_z};
}

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
    // The frame's, not a pass's: the textures as this frame sampled them.
    if (const auto& coverage = scene->alpha_coverage(); !coverage.empty())
        result.slots.put(AlphaCoverageResult{coverage.front().mode, coverage},
                         &alpha_coverage_report);
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
    // alpha_mip_coverage at the cutoffs just set: replaced images retire with the last frame.
    scene->set_alpha_mips(scene::alpha_mip_mode(settings), options.alpha_cutoff,
                          frames->retire_list());
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
    check_request(request);
    const uint32_t width = request.width, height = request.height;
    const std::optional<PixelQuery>& pixel = request.pixel;
    const std::vector<InspectRequest>& inspect = request.inspect;
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
    finish(result, camera, options, pixel, inspect_final);
    return result;
}

}  // namespace ds
