#include "renderer/frame/frame_targets.h"

#include <vector>

#include "renderer/vk/context.h"

namespace ds {
namespace {

constexpr VkFormat kCountFormat = VK_FORMAT_R32_UINT;
// Per counting pass: its shaded counts, then its discarded ones.
constexpr const char* kCountNames[] = {
    "prepass_counts", "prepass_discarded", "forward_counts",     "forward_discarded",
    "decal_counts",   "decal_discarded",   "transparent_counts", "transparent_discarded"};

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
    for (vk::Image& count : counts_) images.push_back(&count);
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
    if (options.count_fragments && !counts_[0]) {
        for (size_t i = 0; i < counts_.size(); ++i)
            counts_[i] = make_image(kCountFormat,
                                    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                    kCountNames[i]);
    }
    ensure_msaa(options.samples, retired);
}

void FrameTargets::import(graph::RenderGraph& graph, const passes::FrameOptions& options,
                          passes::FrameResources& res) {
    auto import_image = [&](const char* name, const vk::Image& image, graph::Semantic semantic,
                            graph::ExternalState initial, graph::ExternalState final) {
        graph::ExternalImage e;
        e.image = image.handle();
        e.view = image.view();
        e.desc = {.format = image.format(),
                  .size = graph::ImageSize::fixed(size_.width, size_.height),
                  .samples = image.samples(),
                  .semantic = semantic};
        e.initial = initial;
        e.final = final;
        return graph.import_image(name, e);
    };
    const graph::Semantic depth_semantic =
        options.reverse_z ? graph::Semantic::ReverseZDepth : graph::Semantic::ForwardZDepth;
    const graph::ExternalState copied = graph::ExternalState::transfer_src();
    res.final_image =
        import_image("final", final_, graph::Semantic::LdrColor, after_copy(), copied);
    res.depth = import_image("depth", depth_, depth_semantic, after_copy(), copied);
    if (options.msaa()) {
        // Last frame's probe read them; the contents are not needed.
        const graph::ExternalState unused = {
            VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE};
        res.msaa_depth = import_image("msaa_depth", msaa_depth_, depth_semantic, unused, probed());
        res.msaa_hdr =
            import_image("msaa_hdr", msaa_hdr_, graph::Semantic::HdrColor, unused, probed());
    }
    if (!options.count_fragments) return;
    // Only passes that run count: the prepass is left out with prepass=off.
    const bool counted[] = {options.prepass, true, options.decal_pass, true};
    passes::CountImages* counting[] = {&res.prepass_counts, &res.forward_counts, &res.decal_counts,
                                       &res.transparent_counts};
    for (size_t i = 0; i < std::size(counting); ++i) {
        if (!counted[i]) continue;
        auto import_count = [&](size_t k) {
            return import_image(kCountNames[k], counts_[k], graph::Semantic::Count, after_copy(),
                                copied);
        };
        counting[i]->shaded = import_count(2 * i);
        counting[i]->discarded = import_count(2 * i + 1);
    }
}

void FrameTargets::reset() {
    msaa_depth_ = vk::Image{};
    msaa_hdr_ = vk::Image{};
    samples_ = VK_SAMPLE_COUNT_1_BIT;
    final_ = vk::Image{};
    depth_ = vk::Image{};
    depth_format_ = VK_FORMAT_UNDEFINED;
    counts_ = {};
    size_ = {0, 0};
}

}  // namespace ds
