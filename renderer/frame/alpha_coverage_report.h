#pragma once
// report.json `alpha_coverage` (alpha_mip_coverage): the frame's, not a pass's — what the
// scene's MASK base colours cover at each mip level, box chain and uploaded chain. The
// renderer puts it into the frame's slots after the joins (GpuScene::alpha_coverage()).
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "renderer/passes/frame_result.h"
#include "renderer/scene/alpha_coverage.h"

namespace ds {

struct AlphaCoverageResult {
    scene::AlphaMipMode mode = scene::AlphaMipMode::Box;
    std::vector<scene::MaterialAlphaCoverage> materials;
};

// {"mode", "materials": [{material, material_index, image, image_index, cutoff, factor_alpha,
// mode, box: [{level, width, height, coverage, relative}], uploaded: [...] (preserve)}], note}
nlohmann::json alpha_coverage_json(const AlphaCoverageResult& result);
void alpha_coverage_report(const AlphaCoverageResult& result, const FrameResult& frame,
                           nlohmann::json& report);

}  // namespace ds
