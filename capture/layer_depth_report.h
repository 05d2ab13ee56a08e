#pragma once
// The report sections of the layer's Z-fight and EQUAL checks (settings zfight, equal_check;
// layer/depth_records.h), from its passes' results, with the draws named as the report names
// them: "zfight" {steps, pixels, pairs (a, b: {draw, instance, name}; pixels, min_steps,
// pass), dropped_records} and "equal_check" {holes, multiple, surfaces, passes}, the shapes of
// depthscope's own sections.
#include <nlohmann/json.hpp>

namespace ds::capture {

// `report`: passes and draws named (write_layer_capture), "settings" set.
void add_layer_depth_sections(nlohmann::json& report);

}  // namespace ds::capture
