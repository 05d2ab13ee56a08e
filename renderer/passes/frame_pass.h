#pragma once
// The one interface of a frame pass (DESIGN.md "How to add a pass"). The renderer keeps one
// ordered list of them (renderer/frame/frame_passes.cpp) and iterates it to build the graph,
// rebuild pipelines, list what was skipped and collect results; it names no pass itself.
// A FramePass may add zero, one or several graph passes; their results come back to it by
// position, never by name.
#include <optional>
#include <span>
#include <string>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_result.h"
#include "renderer/vk/destroy_list.h"

namespace ds::passes {

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
    // Why the settings leave the pass out of this frame ("prepass=off"), for the report;
    // none when it runs, or when it has nothing to do without being switched off (a
    // read-back nobody asked for, a resolve the device does natively).
    virtual std::optional<std::string> skipped(const FrameInputs&) const { return std::nullopt; }
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
};

}  // namespace ds::passes
