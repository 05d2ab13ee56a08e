#pragma once
// The pipelines a geometry pass drew with in one frame and how many draws each recorded
// (PassResult::pipelines). The pass clears it in add(), counts while recording (what
// draw_groups / draw_sorted return) and hands the list over in collect().
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "renderer/passes/frame_result.h"
#include "renderer/passes/pipeline_variants.h"
#include "renderer/spirv/spirv_facts.h"

namespace ds::passes {

// A scene pipeline's PipelineInfo: its name, and the early-Z verdict from the fragment stage it
// was built from (none: depth only) and its alpha-to-coverage state.
inline PipelineInfo describe_pipeline(std::string name, const ShaderStages& stages,
                                      bool alpha_to_coverage) {
    return {std::move(name), spirv::early_z_verdict(stages.frag, alpha_to_coverage),
            !stages.frag.empty()};
}

class PipelineUses {
  public:
    void clear() { list_.clear(); }
    // `draws` more with `info`'s pipeline; a pipeline bound without drawing still appears.
    void add(const PipelineInfo& info, uint32_t draws) {
        auto it = std::find_if(list_.begin(), list_.end(),
                               [&](const PipelineReport& r) { return r.name == info.name; });
        if (it == list_.end())
            it = list_.insert(list_.end(), {info.name, info.early_z, 0, info.fragment_stage});
        it->draws += draws;
    }
    const std::vector<PipelineReport>& list() const { return list_; }

  private:
    std::vector<PipelineReport> list_;
};

}  // namespace ds::passes
