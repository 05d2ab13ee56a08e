#include "renderer/passes/readback_copy.h"

#include <bit>
#include <cstring>

#include "renderer/format/format.h"
#include "renderer/passes/pass_util.h"
#include "renderer/readback/host_readback.h"

namespace ds::passes {
namespace {

constexpr const char* kNames[] = {"readback_final", "readback_depth", "readback_counts"};

bool wants_depth(const FrameInputs& in) {
    return reads_back_fully(in.read_back) || in.options.count_fragments;
}

// The bits a depth texel holds where nothing was drawn (the clear value "far").
uint32_t far_bits(VkFormat format, float far_depth) {
    if (far_depth == 0.0f) return 0u;
    switch (format::depth_bits(format)) {
        case 16:
            return 0xffffu;
        case 24:
            return 0xffffffu;
        default:
            return std::bit_cast<uint32_t>(far_depth);
    }
}

}  // namespace

uint64_t ReadbackCopyPass::covered_texels(std::span<const std::byte> depth, VkFormat format,
                                          float far_depth) {
    const uint32_t far = far_bits(format, far_depth);
    uint64_t covered = 0;
    if (format::depth_bits(format) == 16) {
        for (size_t i = 0; i + 2 <= depth.size(); i += 2) {
            uint16_t v;
            std::memcpy(&v, depth.data() + i, 2);
            covered += v != far;
        }
        return covered;
    }
    // D24 formats leave the top byte undefined.
    const uint32_t mask = format::depth_bits(format) == 24 ? 0xffffffu : 0xffffffffu;
    for (size_t i = 0; i + 4 <= depth.size(); i += 4) {
        uint32_t v;
        std::memcpy(&v, depth.data() + i, 4);
        covered += (v & mask) != far;
    }
    return covered;
}

const char* ReadbackCopyPass::name() const {
    return kNames[size_t(what_)];
}

std::vector<graph::ImageHandle> ReadbackCopyPass::images(const FrameInputs& in,
                                                         const FrameResources& res) const {
    switch (what_) {
        case What::Final:
            if (in.read_back == ReadBack::No) return {};
            return {res.final_image};
        case What::Depth:
            if (!wants_depth(in)) return {};
            return {res.depth};
        case What::Counts: {
            std::vector<graph::ImageHandle> out = count_images(res);
            if (res.zfight.valid()) out.push_back(res.zfight);
            return out;
        }
    }
    return {};
}

void ReadbackCopyPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const std::vector<graph::ImageHandle> sources = images(in, res);
    if (sources.empty()) return;
    services_.readback.add_copy_pass(graph, name(), sources);
}

void ReadbackCopyPass::collect(const FrameCollect& c, std::span<PassResult>, FrameResult& frame) {
    if (what_ == What::Final) {
        const std::span<const std::byte> bytes = c.readback.image_bytes(c.res.final_image);
        frame.rgba8.resize(bytes.size());
        if (!bytes.empty()) std::memcpy(frame.rgba8.data(), bytes.data(), bytes.size());
        return;
    }
    if (what_ != What::Depth) return;  // count sums are the counting passes' to report
    const std::span<const std::byte> depth = c.readback.image_bytes(c.res.depth);
    if (depth.empty()) return;
    const VkFormat format = c.in.options.depth_format;
    frame.covered_pixels = covered_texels(depth, format, c.in.options.far_depth());
    if (c.in.read_back == ReadBack::WithMsaaDepth && c.in.options.msaa() &&
        format::depth_bits(format) == 32) {
        frame.msaa.resolved_depth.resize(depth.size() / sizeof(float));
        std::memcpy(frame.msaa.resolved_depth.data(), depth.data(), depth.size());
    }
}

}  // namespace ds::passes
