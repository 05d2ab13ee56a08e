#include "renderer/frame/frame_passes.h"

#include "renderer/passes/ao_spatial.h"
#include "renderer/passes/ao_temporal.h"
#include "renderer/passes/clear_counts.h"
#include "renderer/passes/contact_shadows.h"
#include "renderer/passes/decals.h"
#include "renderer/passes/depth_precision.h"
#include "renderer/passes/depth_prepass.h"
#include "renderer/passes/depth_resolve.h"
#include "renderer/passes/draw_counts.h"
#include "renderer/passes/equal_check.h"
#include "renderer/passes/forward.h"
#include "renderer/passes/gtao.h"
#include "renderer/passes/hiz.h"
#include "renderer/passes/inspect.h"
#include "renderer/passes/msaa_probe.h"
#include "renderer/passes/msaa_samples.h"
#include "renderer/passes/normals_from_depth.h"
#include "renderer/passes/readback_copy.h"
#include "renderer/passes/shadow.h"
#include "renderer/passes/skybox.h"
#include "renderer/passes/tonemap.h"
#include "renderer/passes/transparent.h"
#include "renderer/passes/zfight.h"

namespace ds {

std::vector<std::unique_ptr<passes::FramePass>> make_frame_passes(const passes::PassServices& s) {
    using namespace passes;
    using Resolve = DepthResolvePass::After;
    using Copy = ReadbackCopyPass::What;
    std::vector<std::unique_ptr<FramePass>> list;
    auto add = [&](std::unique_ptr<FramePass> pass) { list.push_back(std::move(pass)); };
    // Seed 000's frame, with transparent added; each pass decides from the frame's options
    // whether it runs (and says why not).
    add(std::make_unique<ClearCountsPass>(s));
    add(std::make_unique<ShadowPass>(s));
    add(std::make_unique<DepthPrepass>(s));
    add(std::make_unique<DepthResolvePass>(s, Resolve::Prepass));
    add(std::make_unique<HizPass>(s));  // hiz: the pyramid from the prepass depth
    add(std::make_unique<DepthPrecisionPass>(s));
    add(std::make_unique<NormalsFromDepthPass>(s));  // prepass_mode=depth: for gtao, contact
    add(std::make_unique<GtaoPass>(s));
    add(std::make_unique<AoSpatialPass>(s));
    add(std::make_unique<AoTemporalPass>(s));
    add(std::make_unique<ContactShadowsPass>(s));
    add(std::make_unique<ZfightPass>(s));  // diagnostics: against the prepass's result
    add(std::make_unique<ForwardPass>(s));
    // Right after forward, one run: render_path=subpass puts them all in subpass 1 of one
    // render pass. The sky covers only "far" pixels, which no decal does, so its place before
    // decals is free.
    add(std::make_unique<SkyboxPass>(s));
    add(std::make_unique<DecalsPass>(s));  // coplanar overlays, once, over forward's result
    add(std::make_unique<TransparentPass>(s));
    add(std::make_unique<EqualCheckPass>(s));                      // diagnostics: forward's counts
    add(std::make_unique<DepthResolvePass>(s, Resolve::Forward));  // prepass=off, subpass path
    add(std::make_unique<TonemapPass>(s));
    // What the caller reads back, after everything it reads.
    add(std::make_unique<ReadbackCopyPass>(s, Copy::Final));
    add(std::make_unique<ReadbackCopyPass>(s, Copy::Depth));
    add(std::make_unique<ReadbackCopyPass>(s, Copy::Counts));
    add(std::make_unique<DrawCountsPass>(s));  // count_draws: after every pass it reads
    add(std::make_unique<MsaaProbePass>(s));
    add(std::make_unique<MsaaSamplesPass>(s));  // the sample view's rectangle (SampleQuery)
    add(std::make_unique<InspectPass>(s));
    return list;
}

}  // namespace ds
