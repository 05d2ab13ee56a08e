// DepthPrepass's attachments and reads, on either render path (depth_prepass.h).
#include "renderer/passes/depth_prepass.h"

#include "renderer/vk/context.h"

namespace ds::passes {

using graph::Access;

namespace {
constexpr VkClearColorValue kNoNormal{{0.5f, 0.5f, 0.5f, 0.0f}};  // the zero vector
constexpr VkClearColorValue kNoAlphaMip{{DepthPrepass::kAlphaMipNone, 0.0f, 0.0f, 0.0f}};

// alpha_mip: mip levels on a heat scale from "none" (-1, black) up; level 0 is the first
// colour above black, level 8 and beyond white.
const graph::Display kAlphaMipDisplay{.range = graph::DisplayRange::fixed(-1.0f, 8.0f),
                                      .palette = graph::Palette::Heat,
                                      .unit = "mip level",
                                      .legend = "alpha test mip level (-1: not MASK)",
                                      .hover = "alpha test mip level {}",
                                      .exr_channel = "lod"};

graph::ImageDesc alpha_mip_desc(VkSampleCountFlagBits samples) {
    return {.format = DepthPrepass::kAlphaMipFormat,
            .size = graph::ImageSize::relative(1.0f),
            .samples = samples,
            .semantic = graph::Semantic::Scalar,
            .display = kAlphaMipDisplay};
}
}  // namespace

void DepthPrepass::declare(graph::PassBuilder& b, const FrameInputs& in, FrameResources& res) {
    const graph::ImageSize full = graph::ImageSize::relative(1.0f);
    const FrameOptions& o = in.options;
    // prepass_mode=depth: no normals or roughness exist (nor are they listed anywhere).
    if (o.gbuffer) {
        res.normals = b.create_image(
            "normals",
            {.format = kNormalFormat, .size = full, .semantic = graph::Semantic::EncodedNormal});
        res.roughness = b.create_image(
            "roughness",
            {.format = kRoughnessFormat, .size = full, .semantic = graph::Semantic::UnormScalar});
    }
    b.read(res.frame_uniforms, Access::UniformRead,
           graph::Shader::Vertex | graph::Shader::Fragment);
    instrument_.declare(b);
    if (o.surface_id)
        res.surface_id = b.create_image(
            "surface_id",
            {.format = kSurfaceFormat, .size = full, .semantic = graph::Semantic::SurfaceId});
    const graph::DepthUse depth{.load = graph::Load::Clear, .clear = o.far_depth()};
    if (!o.msaa()) {
        b.depth(res.depth, depth);
        if (o.gbuffer) {
            b.color(res.normals, {.load = graph::Load::Clear, .clear = kNoNormal});
            b.color(res.roughness, {.load = graph::Load::Clear});
        }
        // The coverage slot: no image, so the alpha it receives only makes the sample mask.
        if (!o.gbuffer && o.alpha_to_coverage) b.unused_color(kCoverageSlotFormat);
        if (res.surface_id.valid()) b.color(res.surface_id, {.load = graph::Load::Clear});
        if (alpha_mip_)
            b.color(b.create_image("alpha_mip", alpha_mip_desc(VK_SAMPLE_COUNT_1_BIT)),
                    {.load = graph::Load::Clear, .clear = kNoAlphaMip});
        return;
    }
    declare_samples(b, in, res, depth);
}

// At msaa > 1 the samples are kept only where a later pass reads them: forward, skybox and
// transparent LOAD the depth samples (seed 000's lesson); the sample view and zfight the
// surface ids'; normals and roughness are read resolved.
void DepthPrepass::declare_samples(graph::PassBuilder& b, const FrameInputs& in,
                                   FrameResources& res, const graph::DepthUse& depth) {
    const graph::ImageSize full = graph::ImageSize::relative(1.0f);
    const FrameOptions& o = in.options;
    const VkSampleCountFlagBits samples = o.samples;
    graph::ImageHandle msaa_normals, msaa_roughness;
    if (o.gbuffer) {
        msaa_normals = b.create_image("msaa_normals", {.format = kNormalFormat,
                                                       .size = full,
                                                       .samples = samples,
                                                       .semantic = graph::Semantic::EncodedNormal});
        msaa_roughness =
            b.create_image("msaa_roughness", {.format = kRoughnessFormat,
                                              .size = full,
                                              .samples = samples,
                                              .semantic = graph::Semantic::UnormScalar});
        b.color(msaa_normals, {.load = graph::Load::Clear, .clear = kNoNormal});
        b.color(msaa_roughness, {.load = graph::Load::Clear});
        b.resolve(msaa_normals, res.normals);
        b.resolve(msaa_roughness, res.roughness);
    }
    b.depth(res.msaa_depth, depth);
    if (!o.gbuffer && o.alpha_to_coverage) b.unused_color(kCoverageSlotFormat);
    if (res.surface_id.valid()) {
        res.msaa_surface_id =
            b.create_image("msaa_surface_id", {.format = kSurfaceFormat,
                                               .size = full,
                                               .samples = samples,
                                               .semantic = graph::Semantic::SurfaceId});
        b.color(res.msaa_surface_id, {.load = graph::Load::Clear});
        b.resolve(res.msaa_surface_id, res.surface_id,
                  VK_RESOLVE_MODE_SAMPLE_ZERO_BIT);  // integers
    }
    if (alpha_mip_) {  // a float: AVERAGE, the one mode Vulkan allows it
        const graph::ImageHandle samples_image =
            b.create_image("msaa_alpha_mip", alpha_mip_desc(samples));
        b.color(samples_image, {.load = graph::Load::Clear, .clear = kNoAlphaMip});
        b.resolve(samples_image,
                  b.create_image("alpha_mip", alpha_mip_desc(VK_SAMPLE_COUNT_1_BIT)));
    }
    // The nearest sample, natively; without that mode depth_resolve writes res.depth next.
    if (const VkResolveModeFlagBits mode = native_depth_resolve(services_.context.report(), o))
        b.resolve(res.msaa_depth, res.depth, mode);
}

void DepthPrepass::declare_tiled(graph::PassBuilder& b, const FrameInputs& in,
                                 FrameResources& res) {
    const graph::ImageSize full = graph::ImageSize::relative(1.0f);
    const VkSampleCountFlagBits samples = in.options.samples;
    const bool msaa = in.options.msaa();
    // Attachment 0, the light (seed 002): what forward lights into in the next subpass. At 1x
    // this pass creates res.hdr (forward does on the dynamic path).
    if (!msaa)
        res.hdr = b.create_image(
            "hdr", {.format = kHdrFormat, .size = full, .semantic = graph::Semantic::HdrColor});
    VkClearColorValue background{};
    for (size_t i = 0; i < 4; ++i) background.float32[i] = kHdrBackground[i];
    b.color(msaa ? res.msaa_hdr : res.hdr, {.load = graph::Load::Clear, .clear = background});
    if (in.options.gbuffer) {
        // Never resolved: at msaa > 1 forward reads each sample; at 1x they are the same.
        res.normals = b.create_image(msaa ? "msaa_normals" : "normals",
                                     {.format = kNormalFormat,
                                      .size = full,
                                      .samples = samples,
                                      .semantic = graph::Semantic::EncodedNormal});
        res.roughness = b.create_image(msaa ? "msaa_roughness" : "roughness",
                                       {.format = kRoughnessFormat,
                                        .size = full,
                                        .samples = samples,
                                        .semantic = graph::Semantic::UnormScalar});
        b.color(res.normals, {.load = graph::Load::Clear, .clear = kNoNormal});
        b.color(res.roughness, {.load = graph::Load::Clear});
    }
    b.depth(msaa ? res.msaa_depth : res.depth,
            {.load = graph::Load::Clear, .clear = in.options.far_depth()});
    b.read(res.frame_uniforms, Access::UniformRead,
           graph::Shader::Vertex | graph::Shader::Fragment);
    instrument_.declare(b);
}

}  // namespace ds::passes
