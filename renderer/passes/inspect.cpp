#include "renderer/passes/inspect.h"

#include <cstring>
#include <string>
#include <utility>

#include "renderer/format/format.h"
#include "renderer/readback/host_readback.h"

namespace ds::passes {
namespace {

constexpr VkFormat kTexelFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr const char* kShader = "inspect.comp";
constexpr const char* kFinal = "final";  // read back as it is (ReadbackCopyPass)

ComputeKernel make_decode_kernel(const PassServices& services) {
    return ComputeKernel(services, kShader, {KernelBinding::Sampled, KernelBinding::Storage},
                         sizeof(int32_t), InspectPass::kMaxImages);
}

size_t index_of(bool uint_source, bool multisampled) {
    return (uint_source ? 2u : 0u) + (multisampled ? 1u : 0u);
}

std::vector<shader::Define> defines_of(size_t index) {
    return {{"UINT_SOURCE", index & 2u ? "1" : "0"}, {"MULTISAMPLED", index & 1u ? "1" : "0"}};
}

// The i-th image's transient: names stay the same from frame to frame, so each keeps its
// host buffer ("readback_<name>") while its size does.
std::string texels_name(size_t i) {
    return i == 0 ? std::string("inspect_texels") : "inspect_texels_" + std::to_string(i);
}

}  // namespace

InspectPass::InspectPass(const PassServices& services)
    : services_(services),
      kernels_{make_decode_kernel(services), make_decode_kernel(services),
               make_decode_kernel(services), make_decode_kernel(services)} {}

ComputeKernel& InspectPass::kernel(bool uint_source, bool multisampled) {
    const size_t i = index_of(uint_source, multisampled);
    if (!built_[i]) {  // built on first use: most sessions never inspect an integer image
        vk::DestroyList nothing_in_flight;
        kernels_[i].rebuild(nothing_in_flight, defines_of(i));
        built_[i] = true;
    }
    return kernels_[i];
}

void InspectPass::rebuild_pipelines(vk::DestroyList& retired) {
    std::array<std::optional<ComputeKernel::Prepared>, 4> prepared;
    for (size_t i = 0; i < kernels_.size(); ++i)
        if (built_[i]) prepared[i] = kernels_[i].prepare(defines_of(i));
    for (size_t i = 0; i < kernels_.size(); ++i)
        if (prepared[i]) kernels_[i].install(std::move(*prepared[i]), retired);
}

std::vector<InspectPass::Read> InspectPass::plan(const graph::RenderGraph& graph,
                                                 const FrameInputs& in) const {
    const std::vector<InspectRequest>& wanted = in.inspect;
    std::vector<Read> reads;
    for (size_t i = 0; i < wanted.size() && reads.size() < kMaxImages; ++i) {
        if (wanted[i].resource.empty() || wanted[i].resource == kFinal) continue;
        const graph::ImageHandle source = graph.find_image(wanted[i].resource);
        if (!source.valid()) continue;  // its pass is off this frame
        const graph::ResourceInfo& info = graph.resources()[source.index];
        Read r;
        r.source = source;
        r.primary = i == 0;
        r.info.name = wanted[i].resource;
        r.info.format = info.image.format;
        r.info.semantic = info.image.semantic;
        r.info.display = info.image.display;
        r.info.width = info.extent.width;
        r.info.height = info.extent.height;
        r.info.samples = uint32_t(info.image.samples);
        r.info.sample = wanted[i].sample < r.info.samples ? wanted[i].sample : 0;
        reads.push_back(std::move(r));
    }
    return reads;
}

void InspectPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources&) {
    reads_ = plan(graph, in);
    if (reads_.empty()) return;
    // Built here, not while recording: a shader error surfaces before the frame is recorded.
    for (const Read& r : reads_) kernel(format::is_integer(r.info.format), r.info.samples > 1);
    struct Data {};
    graph.add_pass<Data>(
        {name(), graph::PassKind::Compute, role()},
        [&](graph::PassBuilder& b, Data&) {
            for (size_t i = 0; i < reads_.size(); ++i) {
                Read& r = reads_[i];
                r.texels = b.create_image(
                    texels_name(i), {.format = kTexelFormat,
                                     .size = graph::ImageSize::fixed(r.info.width, r.info.height),
                                     .semantic = graph::Semantic::Other});
                b.read(r.source, graph::Access::Sampled);  // twice is one access
                b.write(r.texels, graph::Access::StorageWrite);
            }
        },
        [this, frame_set = in.frame_set, frame = in.frame_number](graph::PassContext& ctx,
                                                                  const Data&) {
            for (uint32_t i = 0; i < reads_.size(); ++i) {
                const Read& r = reads_[i];
                ComputeKernel& k = kernel(format::is_integer(r.info.format), r.info.samples > 1);
                const BoundImage images[] = {{ctx.view(r.source), ctx.layout(r.source)},
                                             {ctx.view(r.texels), ctx.layout(r.texels)}};
                const int32_t sample_index = int32_t(r.info.sample);
                k.dispatch(ctx.cmd(), frame_set, frame, images, &sample_index,
                           {r.info.width, r.info.height}, /*slot=*/i);
            }
        });
    std::vector<graph::ImageHandle> copies;
    for (const Read& r : reads_) copies.push_back(r.texels);
    services_.readback.add_copy_pass(graph, "readback_inspect", std::move(copies));
}

void InspectPass::collect(const FrameCollect& c, std::span<PassResult>, FrameResult& frame) {
    for (const Read& r : reads_) {
        const std::span<const std::byte> bytes = c.readback.image_bytes(r.texels);
        if (bytes.empty()) continue;
        InspectedImage image = r.info;
        image.texels.resize(size_t(image.width) * image.height * 4);
        std::memcpy(image.texels.data(), bytes.data(),
                    std::min(bytes.size(), image.texels.size() * sizeof(float)));
        if (r.primary)
            frame.inspected = std::move(image);
        else
            frame.overlays.push_back(std::move(image));
    }
}

}  // namespace ds::passes
