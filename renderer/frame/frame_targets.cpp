#include "renderer/frame/frame_targets.h"

#include <vector>

#include "renderer/vk/context.h"

namespace ds {
namespace {

// The graph leaves these imports in TRANSFER_SRC after the frame (what readback_* copies
// from), and the previous frame's copy (or that final barrier) was the last to touch them;
// the contents are not needed.
graph::ExternalState after_copy() {
    return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
}

// msaa_probe samples the multisampled images last, in a compute shader.
graph::ExternalState probed() {
    return {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
}

}  // namespace

FrameTargets::FrameTargets(vk::Context& context, VkFormat final_format, VkFormat hdr_format)
    : context_(context), final_format_(final_format), hdr_format_(hdr_format) {}

vk::Image FrameTargets::make_image(VkFormat format, VkImageUsageFlags usage,
                                   const char* name) const {
    return vk::Image(context_,
                     {size_.width, size_.height, 1, format,
                      usage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                      VK_SAMPLE_COUNT_1_BIT, name});
}

// A new depth format replaces both depth images; ensure_msaa makes the multisampled one again.
void FrameTargets::ensure_depth(VkFormat format, vk::DestroyList& retired) {
    if (format == depth_format_ && depth_) return;
    for (vk::Image* image : {&depth_, &msaa_depth_}) {
        if (*image) retired.defer(std::move(*image));
        *image = vk::Image{};
    }
    depth_format_ = format;
    depth_ = make_image(format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "depth");
}

void FrameTargets::ensure_msaa(VkSampleCountFlagBits samples, vk::DestroyList& retired) {
    if (samples == samples_ && (samples == VK_SAMPLE_COUNT_1_BIT || msaa_depth_)) return;
    if (msaa_depth_) retired.defer(std::move(msaa_depth_));
    if (msaa_hdr_) retired.defer(std::move(msaa_hdr_));
    msaa_depth_ = vk::Image{};
    msaa_hdr_ = vk::Image{};
    samples_ = samples;
    if (samples == VK_SAMPLE_COUNT_1_BIT) return;  // at 1x no multisampled image exists
    msaa_depth_ = vk::Image(
        context_, {size_.width, size_.height, 1, depth_format_,
                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                   samples, "msaa_depth"});
    msaa_hdr_ =
        vk::Image(context_, {size_.width, size_.height, 1, hdr_format_,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                             samples, "msaa_hdr"});
}

void FrameTargets::retire_all(vk::DestroyList& retired) {
    std::vector<vk::Image*> images = {&msaa_depth_, &msaa_hdr_, &final_, &depth_};
    for (vk::Image* image : images) {
        if (*image) retired.defer(std::move(*image));
        *image = vk::Image{};
    }
}

void FrameTargets::ensure(VkExtent2D size, const passes::FrameOptions& options,
                          vk::DestroyList& retired) {
    if (size.width != size_.width || size.height != size_.height) {
        retire_all(retired);
        size_ = size;
    }
    if (!final_) final_ = make_image(final_format_, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, "final");
    ensure_depth(options.depth_format, retired);
    ensure_msaa(options.samples, retired);
}

void FrameTargets::import(graph::RenderGraph& graph, const passes::FrameOptions& options,
                          passes::FrameResources& res) const {
    const VkExtent2D size = graph.output_extent();
    auto import_image = [&](const char* name, VkFormat format, VkSampleCountFlagBits samples,
                            graph::Semantic semantic, graph::ExternalState initial,
                            graph::ExternalState final) {
        graph::ExternalImage e;  // handles come with bind()
        e.desc = {.format = format,
                  .size = graph::ImageSize::fixed(size.width, size.height),
                  .samples = samples,
                  .semantic = semantic};
        e.initial = initial;
        e.final = final;
        return graph.import_image(name, e);
    };
    const graph::Semantic depth_semantic =
        options.reverse_z ? graph::Semantic::ReverseZDepth : graph::Semantic::ForwardZDepth;
    const graph::ExternalState copied = graph::ExternalState::transfer_src();
    const VkSampleCountFlagBits one = VK_SAMPLE_COUNT_1_BIT;
    res.final_image =
        import_image("final", final_format_, one, graph::Semantic::LdrColor, after_copy(), copied);
    res.depth =
        import_image("depth", options.depth_format, one, depth_semantic, after_copy(), copied);
    if (options.msaa()) {
        // Last frame's probe read them; the contents are not needed.
        const graph::ExternalState unused = {
            VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE};
        res.msaa_depth = import_image("msaa_depth", options.depth_format, options.samples,
                                      depth_semantic, unused, probed());
        res.msaa_hdr = import_image("msaa_hdr", hdr_format_, options.samples,
                                    graph::Semantic::HdrColor, unused, probed());
    }
}

void FrameTargets::bind(graph::RenderGraph& graph, const passes::FrameResources& res) const {
    graph.bind_import(res.final_image, final_.handle(), final_.view());
    graph.bind_import(res.depth, depth_.handle(), depth_.view(), depth_.attachment_view());
    if (res.msaa_depth.valid())
        graph.bind_import(res.msaa_depth, msaa_depth_.handle(), msaa_depth_.view(),
                          msaa_depth_.attachment_view());
    if (res.msaa_hdr.valid()) graph.bind_import(res.msaa_hdr, msaa_hdr_.handle(), msaa_hdr_.view());
}

void FrameTargets::reset() {
    msaa_depth_ = vk::Image{};
    msaa_hdr_ = vk::Image{};
    samples_ = VK_SAMPLE_COUNT_1_BIT;
    final_ = vk::Image{};
    depth_ = vk::Image{};
    depth_format_ = VK_FORMAT_UNDEFINED;
    size_ = {0, 0};
}

}  // namespace ds
