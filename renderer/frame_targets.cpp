#include "renderer/frame_targets.h"

#include <bit>
#include <cstring>

#include "renderer/vk/barrier.h"
#include "renderer/vk/context.h"

namespace ds {
namespace {

constexpr VkFormat kCountFormat = VK_FORMAT_R32_UINT;
constexpr const char* kCountNames[] = {"prepass_counts", "forward_counts", "transparent_counts"};

// Depth texels copy out as 4 bytes (D24 in the low bits of a word, D32 as a float) or 2 (D16).
uint32_t depth_texel_bytes(VkFormat format) {
    return format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D16_UNORM_S8_UINT ? 2u : 4u;
}

// The bits a texel holds where nothing was drawn (the clear value "far").
uint32_t far_bits(VkFormat format, float far_depth) {
    if (far_depth == 0.0f) return 0u;
    switch (format) {
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_D16_UNORM_S8_UINT:
            return 0xffffu;
        case VK_FORMAT_D24_UNORM_S8_UINT:
        case VK_FORMAT_X8_D24_UNORM_PACK32:
            return 0xffffffu;
        default:
            return std::bit_cast<uint32_t>(far_depth);
    }
}

// The graph leaves every import in TRANSFER_SRC after the frame, and the previous frame's
// copy (or that final barrier) was the last to touch it; the contents are not needed.
graph::ExternalState after_copy() {
    return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
}

// MsaaProbe samples the multisampled images after the graph, in a compute shader.
graph::ExternalState probed(VkImageLayout layout) {
    return {layout, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
}

}  // namespace

FrameTargets::FrameTargets(vk::Context& context, VkFormat final_format, VkFormat depth_format,
                           VkFormat hdr_format)
    : context_(context),
      final_format_(final_format),
      depth_format_(depth_format),
      hdr_format_(hdr_format) {}

FrameTargets::Target FrameTargets::make_target(VkFormat format, VkImageUsageFlags usage,
                                               uint32_t bytes_per_texel, const char* name) const {
    Target t;
    t.image =
        vk::Image(context_, {size_.width, size_.height, 1, format,
                             usage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                             VK_SAMPLE_COUNT_1_BIT, name});
    t.readback =
        vk::Buffer(context_, {VkDeviceSize(size_.width) * size_.height * bytes_per_texel,
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::Readback, name});
    return t;
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

void FrameTargets::ensure(VkExtent2D size, bool counts, VkSampleCountFlagBits samples,
                          vk::DestroyList& retired) {
    if (size.width != size_.width || size.height != size_.height) {
        if (msaa_depth_) retired.defer(std::move(msaa_depth_));
        if (msaa_hdr_) retired.defer(std::move(msaa_hdr_));
        msaa_depth_ = vk::Image{};
        msaa_hdr_ = vk::Image{};
        if (final_.image) retired.defer(std::move(final_));
        if (depth_.image) retired.defer(std::move(depth_));
        for (Target& t : counts_)
            if (t.image) retired.defer(std::move(t));
        final_ = Target{};
        depth_ = Target{};
        counts_ = {};
        size_ = size;
    }
    if (!final_.image) {
        final_ = make_target(final_format_, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, 4, "final");
        depth_ = make_target(depth_format_, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                             depth_texel_bytes(depth_format_), "depth");
    }
    if (counts && !counts_[0].image) {
        for (size_t i = 0; i < counts_.size(); ++i)
            counts_[i] = make_target(kCountFormat,
                                     VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     4, kCountNames[i]);
    }
    ensure_msaa(samples, retired);
}

void FrameTargets::import(graph::RenderGraph& graph, const passes::FrameOptions& options,
                          passes::FrameResources& res) {
    auto import_target = [&](const char* name, const Target& t, graph::Semantic semantic) {
        graph::ExternalImage e;
        e.image = t.image.handle();
        e.view = t.image.view();
        e.desc = {.format = t.image.format(),
                  .size = graph::ImageSize::fixed(size_.width, size_.height),
                  .semantic = semantic};
        e.initial = after_copy();
        e.final = graph::ExternalState::transfer_src();
        return graph.import_image(name, e);
    };
    res.final_image = import_target("final", final_, graph::Semantic::LdrColor);
    res.depth = import_target(
        "depth", depth_,
        options.reverse_z ? graph::Semantic::ReverseZDepth : graph::Semantic::ForwardZDepth);
    if (options.msaa()) {
        const graph::Semantic depth_semantic =
            options.reverse_z ? graph::Semantic::ReverseZDepth : graph::Semantic::ForwardZDepth;
        auto import_msaa = [&](const char* name, const vk::Image& image, graph::Semantic semantic,
                               VkImageLayout final_layout) {
            graph::ExternalImage e;
            e.image = image.handle();
            e.view = image.view();
            e.desc = {.format = image.format(),
                      .size = graph::ImageSize::fixed(size_.width, size_.height),
                      .samples = samples_,
                      .semantic = semantic};
            // Last frame's probe read it; the contents are not needed.
            e.initial = {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                         VK_ACCESS_2_NONE};
            e.final = probed(final_layout);
            return graph.import_image(name, e);
        };
        res.msaa_depth = import_msaa("msaa_depth", msaa_depth_, depth_semantic,
                                     VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
        res.msaa_hdr = import_msaa("msaa_hdr", msaa_hdr_, graph::Semantic::HdrColor,
                                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
    counted_ = {};
    if (!options.count_fragments) return;
    // Only passes that run count: the prepass is left out with prepass=off.
    counted_ = {options.prepass, true, true};
    graph::ImageHandle* handles[] = {&res.prepass_counts, &res.forward_counts,
                                     &res.transparent_counts};
    for (size_t i = 0; i < counts_.size(); ++i)
        if (counted_[i])
            *handles[i] = import_target(kCountNames[i], counts_[i], graph::Semantic::Count);
}

void FrameTargets::copy(VkCommandBuffer cmd, const Target& t) const {
    VkBufferImageCopy region{};  // bufferRowLength 0: tightly packed, row 0 = top
    region.imageSubresource = {t.image.aspect() & ~VkImageAspectFlags(VK_IMAGE_ASPECT_STENCIL_BIT),
                               0, 0, 1};
    region.imageExtent = {size_.width, size_.height, 1};
    vkCmdCopyImageToBuffer(cmd, t.image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           t.readback.handle(), 1, &region);
}

void FrameTargets::record_read_back(VkCommandBuffer cmd, bool image, bool depth) const {
    if (image) copy(cmd, final_);
    if (depth) copy(cmd, depth_);
    for (size_t i = 0; i < counts_.size(); ++i)
        if (counted_[i]) copy(cmd, counts_[i]);
    vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

std::vector<uint8_t> FrameTargets::rgba8() const {
    final_.readback.invalidate();
    const size_t bytes = size_t(size_.width) * size_.height * 4;
    std::vector<uint8_t> out(bytes);
    std::memcpy(out.data(), final_.readback.mapped(), bytes);
    return out;
}

uint64_t FrameTargets::covered_pixels(float far_depth) const {
    depth_.readback.invalidate();
    const size_t texels = size_t(size_.width) * size_.height;
    const std::byte* data = depth_.readback.mapped();
    const uint32_t far = far_bits(depth_format_, far_depth);
    uint64_t covered = 0;
    if (depth_texel_bytes(depth_format_) == 2) {
        for (size_t i = 0; i < texels; ++i) {
            uint16_t v;
            std::memcpy(&v, data + 2 * i, 2);
            covered += v != far;
        }
        return covered;
    }
    // D24 formats leave the top byte undefined.
    const bool d24 = depth_format_ == VK_FORMAT_D24_UNORM_S8_UINT ||
                     depth_format_ == VK_FORMAT_X8_D24_UNORM_PACK32;
    const uint32_t mask = d24 ? 0xffffffu : 0xffffffffu;
    for (size_t i = 0; i < texels; ++i) {
        uint32_t v;
        std::memcpy(&v, data + 4 * i, 4);
        covered += (v & mask) != far;
    }
    return covered;
}

std::optional<uint64_t> FrameTargets::count_sum(CountImage which) const {
    const size_t i = size_t(which);
    if (!counted_[i]) return std::nullopt;
    counts_[i].readback.invalidate();
    const size_t texels = size_t(size_.width) * size_.height;
    const std::byte* data = counts_[i].readback.mapped();
    uint64_t sum = 0;
    for (size_t t = 0; t < texels; ++t) {
        uint32_t v;
        std::memcpy(&v, data + 4 * t, 4);
        sum += v;
    }
    return sum;
}

std::vector<float> FrameTargets::depth_floats() const {
    if (depth_format_ != VK_FORMAT_D32_SFLOAT && depth_format_ != VK_FORMAT_D32_SFLOAT_S8_UINT)
        return {};
    depth_.readback.invalidate();
    std::vector<float> out(size_t(size_.width) * size_.height);
    std::memcpy(out.data(), depth_.readback.mapped(), out.size() * sizeof(float));
    return out;
}

void FrameTargets::reset() {
    msaa_depth_ = vk::Image{};
    msaa_hdr_ = vk::Image{};
    samples_ = VK_SAMPLE_COUNT_1_BIT;
    final_ = Target{};
    depth_ = Target{};
    counts_ = {};
    size_ = {0, 0};
}

}  // namespace ds
