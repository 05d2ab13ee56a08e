#include "renderer/frame/frame_passes.h"

#include <functional>

#include "renderer/frame/frame_joins.h"

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
#include "renderer/passes/triangle_size.h"
#include "renderer/passes/zfight.h"

namespace ds {
namespace {

using namespace passes;
using Resolve = DepthResolvePass::After;
using Copy = ReadbackCopyPass::What;

// One line of the list: how to make the pass and, where it has any, its knobs.
struct Entry {
    std::vector<SettingDef> (*knobs)() = nullptr;
    std::function<std::unique_ptr<FramePass>(const PassServices&)> make;
};

template <typename Pass, typename... Args>
Entry pass(Args... args) {
    Entry e;
    if constexpr (requires { Pass::knobs(); }) e.knobs = &Pass::knobs;
    e.make = [=](const PassServices& s) { return std::make_unique<Pass>(s, args...); };
    return e;
}

// Seed 000's frame, with transparent added; each pass decides from the frame's settings
// whether it runs (and says why not).
const std::vector<Entry>& pass_list() {
    static const std::vector<Entry> list = {
        pass<ClearCountsPass>(),
        pass<ShadowPass>(),
        pass<DepthPrepass>(),
        pass<DepthResolvePass>(Resolve::Prepass),
        pass<HizPass>(),  // hiz: the pyramid from the prepass depth
        pass<DepthPrecisionPass>(),
        pass<NormalsFromDepthPass>(),  // prepass_mode=depth: for gtao, contact
        pass<GtaoPass>(),
        pass<AoSpatialPass>(),
        pass<AoTemporalPass>(),
        pass<ContactShadowsPass>(),
        pass<ZfightPass>(),  // diagnostics: against the prepass's result
        pass<TriangleSizePass>(),
        pass<ForwardPass>(),
        // Right after forward, one run: render_path=subpass puts them all in subpass 1 of one
        // render pass. The sky covers only "far" pixels, which no decal does, so its place
        // before decals is free.
        pass<SkyboxPass>(),
        pass<DecalsPass>(),  // coplanar overlays, once, over forward's result
        pass<TransparentPass>(),
        pass<EqualCheckPass>(),                    // diagnostics: forward's counts
        pass<DepthResolvePass>(Resolve::Forward),  // prepass=off, subpass path
        pass<TonemapPass>(),
        // What the caller reads back, after everything it reads.
        pass<ReadbackCopyPass>(Copy::Final),
        pass<ReadbackCopyPass>(Copy::Depth),
        pass<ReadbackCopyPass>(Copy::Counts),
        pass<DrawCountsPass>(),  // count_draws: after every pass it reads
        pass<MsaaProbePass>(),
        pass<MsaaSamplesPass>(),  // the sample view's rectangle (SampleQuery)
        pass<InspectPass>(),
    };
    return list;
}

// The registry's pass knobs come from the list (settings/knob.h).
const KnobSource kPassKnobs(KnobOwner::Passes, &frame_pass_knobs);

}  // namespace

std::vector<std::unique_ptr<FramePass>> make_frame_passes(const PassServices& s) {
    std::vector<std::unique_ptr<FramePass>> out;
    for (const Entry& e : pass_list()) out.push_back(e.make(s));
    return out;
}

std::vector<SettingDef> frame_pass_knobs() {
    return gather_knobs(pass_list());
}

std::span<const FrameJoin> frame_joins() {
    static constexpr FrameJoin joins[] = {&join_hiz_draws};
    return joins;
}

}  // namespace ds
