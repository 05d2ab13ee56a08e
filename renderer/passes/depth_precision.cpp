#include "renderer/passes/depth_precision.h"

#include "renderer/format/format.h"

namespace ds::passes {

using graph::Access;

DepthPrecisionPass::DepthPrecisionPass(const PassServices& services)
    : kernel_(services, "depth_precision.comp", {KernelBinding::Sampled, KernelBinding::Storage},
              sizeof(uint32_t)) {}

void DepthPrecisionPass::rebuild_pipelines(vk::DestroyList& retired) {
    if (built_) kernel_.rebuild(retired);
}

std::vector<SettingDef> DepthPrecisionPass::knobs() {
    return {bool_knob(kKnob, "diagnostics", false,
                      "image depth_precision: per pixel, the distance along the view ray to the "
                      "next representable depth value (format, planes, direction), in scene "
                      "units (on whenever zfight is)",
                      Invalidates::Nothing)};
}

void DepthPrecisionPass::configure(const FrameSetup& setup, FrameOptions& o) {
    if (!knob_value(setup.settings, kKnob)) return;
    o.requests.depth_precision = true;
    if (o.subpass) set_turned_off(kKnob.name);
}

void DepthPrecisionPass::resolve(FrameOptions& o) {
    o.depth_precision = o.requests.depth_precision && o.prepass && !o.subpass;
}

void DepthPrecisionPass::add(graph::RenderGraph& graph, const FrameInputs& in,
                             FrameResources& res) {
    if (!in.options.depth_precision) return;
    if (!built_) {  // on first use: most sessions never look at it
        vk::DestroyList nothing_in_flight;
        kernel_.rebuild(nothing_in_flight);
        built_ = true;
    }
    const uint32_t depth_bits = format::depth_bits(in.options.depth_format);
    struct Data {
        graph::ImageHandle depth, out;
    };
    const Data& data = graph.add_pass<Data>(
        {name(), graph::PassKind::Compute},
        [&](graph::PassBuilder& b, Data& d) {
            d.out = b.create_image("depth_precision", {.format = kFormat,
                                                       .size = graph::ImageSize::relative(1.0f),
                                                       .semantic = graph::Semantic::DepthStep});
            b.read(res.frame_uniforms, Access::UniformRead);
            d.depth = b.read(res.depth, Access::Sampled);
            b.write(d.out, Access::StorageWrite);
        },
        [this, depth_bits, frame_set = in.frame_set, frame = in.frame_number](
            graph::PassContext& ctx, const Data& d) {
            const BoundImage images[] = {{ctx.view(d.depth), ctx.layout(d.depth)},
                                         {ctx.view(d.out), ctx.layout(d.out)}};
            kernel_.dispatch(ctx.cmd(), frame_set, frame, images, &depth_bits, ctx.extent(d.out));
        });
    res.depth_precision = data.out;
}

}  // namespace ds::passes
