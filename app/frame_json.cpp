#include "app/frame_json.h"

namespace ds::app {

nlohmann::json passes_json(const FrameResult& frame) {
    nlohmann::json passes = nlohmann::json::array();
    for (const PassResult& p : frame.passes) {
        nlohmann::json pass = {
            {"name", p.name},
            {"kind", graph::pass_role_name(p.role)},
            {"gpu_ms", p.gpu_ms},
            {"stats",
             {{"vertex_shader_invocations", p.vertex_shader_invocations},
              {"fragment_shader_invocations", p.fragment_shader_invocations},
              {"clipping_primitives", p.clipping_primitives}}},
        };
        if (p.shaded_fragments) pass["shaded_fragments"] = *p.shaded_fragments;
        passes.push_back(std::move(pass));
    }
    return passes;
}

nlohmann::json counters_note() {
    return {
        {"stats",
         "the device's pipeline statistics; lavapipe counts fragment shader invocations once "
         "per rasterized 4x4 block, before the depth test, so they cannot show what a prepass "
         "saves"},
        {"shaded_fragments",
         "exact: fragments that ran the fragment shader after the depth and alpha tests, "
         "counted per pixel by the shaders (count_fragments=on)"},
    };
}

}  // namespace ds::app
