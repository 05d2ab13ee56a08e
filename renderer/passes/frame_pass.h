#pragma once
// The one interface of a frame pass (DESIGN.md "How to add a pass"). The renderer keeps one
// ordered list of them (renderer/frame/frame_passes.cpp) and iterates it to configure the
// frame, build the graph, rebuild pipelines, list what was skipped and collect results; it
// names no pass itself. A pass owns its knobs (declared in its file, gathered from the pass
// list), its options and gate (configure), its result type (put into FrameResult's slots by
// collect, with the function that writes its report.json section).
// A FramePass may add zero, one or several graph passes; their results come back to it by
// position, never by name.
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_result.h"
#include "renderer/vk/destroy_list.h"

namespace ds::vk {
struct DeviceReport;
}

namespace ds::passes {

// What a pass may look at to decide this frame's options (FramePass::configure).
struct FrameSetup {
    const Settings& settings;
    const GpuScene& scene;
    const vk::DeviceReport& device;
    const RenderRequest& request;
};

// What a pass may read after the frame's fence to fill in its results.
struct FrameCollect {
    const FrameInputs& in;
    const FrameResources& res;
    const HostReadback& readback;
};

// A frame pass's own graph pass among those it added (FramePass::collect's `own`): the first
// of the Frame role, since a pixel history replay comes before it and a measurement after it.
// Null when it added none.
inline PassResult* frame_result(std::span<PassResult> own) {
    for (PassResult& p : own)
        if (p.role == graph::PassRole::Frame) return &p;
    return nullptr;
}

class FramePass {
  public:
    virtual ~FramePass() = default;

    // The name of its (main) graph pass: what the skipped list says.
    virtual const char* name() const = 0;

    // Frame work, a clear, or a read-back: the role of every graph pass it adds.
    virtual graph::PassRole role() const { return graph::PassRole::Frame; }
    // Reads the pass's own knobs (the one source of whether it runs this frame and why not:
    // set_skipped, set_turned_off), sets the frame facts it owns that other passes read, and
    // requests what it needs of other passes (FrameOptions::requests). Called for every pass
    // in list order before any add().
    virtual void configure(const FrameSetup& /*setup*/, FrameOptions& /*options*/) {}
    // After every configure(): a pass that provides something to others (surface ids, counts,
    // depth precision) turns the requests into its decision.
    virtual void resolve(FrameOptions& /*options*/) {}
    // Why the settings leave the pass out of this frame ("prepass=off"), for the report;
    // none when it runs, or when it has nothing to do without being switched off (a
    // read-back nobody asked for, a resolve the device does natively).
    const std::optional<std::string>& skipped() const { return skipped_; }
    // Its knobs that are on but do not run on render_path=subpass (report tiler.turned_off).
    const std::vector<std::string>& turned_off() const { return turned_off_; }
    // The renderer clears the gate before configure().
    void clear_gate() {
        skipped_.reset();
        turned_off_.clear();
    }
    // Declares its graph passes from the frame's inputs and what earlier passes wrote into
    // `res`; adds nothing when it does not run.
    virtual void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) = 0;
    // Hot reload, fail-safe: a shader error throws and leaves the current pipelines in place.
    virtual void rebuild_pipelines(vk::DestroyList& retired) = 0;
    // msaa differs from the previous frame's (pipelines are kept per sample count; a pass
    // with per-count resources can let them go).
    virtual void on_sample_count_changed(VkSampleCountFlagBits /*samples*/) {}
    // After the fence: `own` are the results of the graph passes it added, in order (empty
    // when it added none); frame-level results (counts, read-back data) go into `frame`.
    virtual void collect(const FrameCollect&, std::span<PassResult> /*own*/,
                         FrameResult& /*frame*/) {}

  protected:
    void set_skipped(std::string why) { skipped_ = std::move(why); }
    void set_turned_off(std::string knob) { turned_off_.push_back(std::move(knob)); }

  private:
    std::optional<std::string> skipped_;
    std::vector<std::string> turned_off_;
};

}  // namespace ds::passes
