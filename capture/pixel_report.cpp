#include "capture/pixel_report.h"

#include <cstdio>

#include "renderer/format/format.h"
#include "renderer/view/decode.h"

namespace ds::capture {
namespace {

nlohmann::json rgba_json(const std::optional<std::array<float, 4>>& c) {
    if (!c) return nullptr;
    return {(*c)[0], (*c)[1], (*c)[2], (*c)[3]};
}

float linear(const FrameResult& frame, float depth) {
    const DepthResult& d = *frame.depth;
    return view::linear_depth(depth, d.reverse_z, d.znear, d.zfar);
}

nlohmann::json fragment_json(const PixelReportInput& in, const PixelFragment& f) {
    const SurfaceName name = in.scene.instance_name(f.instance);
    nlohmann::json alpha = nullptr;
    if (f.alpha_test)
        alpha = {{"alpha", f.alpha_test->alpha},
                 {"cutoff", f.alpha_test->cutoff},
                 {"passed", f.alpha_test->passed}};
    return {{"pass", f.pass},
            {"mesh", name.mesh},
            {"material", name.material},
            {"node", name.node},
            {"instance", f.instance},
            {"primitive", f.primitive},
            {"sample", f.sample},
            {"depth", f.depth},
            {"linear_depth", linear(in.frame, f.depth)},
            {"depth_test", {{"passed", f.depth_passed}, {"against", f.against}}},
            {"alpha_test", alpha},
            {"shaded", f.shaded},
            {"color", rgba_json(f.color)},
            {"blended", rgba_json(f.blended)}};
}

// The final image's texel (sRGB-encoded 8-bit), when it was read back.
nlohmann::json final_color(const FrameResult& frame, const PixelHistory& h) {
    const size_t i = (size_t(h.y) * frame.width + h.x) * 4;
    if (frame.rgba8.size() < i + 4) return nullptr;
    return {frame.rgba8[i], frame.rgba8[i + 1], frame.rgba8[i + 2], frame.rgba8[i + 3]};
}

// GPU ms of the replays (graph role history) and of the frame's own passes.
std::pair<double, double> replay_and_frame_ms(const FrameResult& frame) {
    double replay = 0, own = 0;
    for (const PassResult& p : frame.passes) {
        if (p.role == graph::PassRole::History) replay += p.gpu_ms;
        if (p.role == graph::PassRole::Frame) own += p.gpu_ms;
    }
    return {replay, own};
}

std::string rgba_text(const std::optional<std::array<float, 4>>& c) {
    if (!c) return "-";
    char text[64];
    std::snprintf(text, sizeof text, "%.3f %.3f %.3f %.3f", (*c)[0], (*c)[1], (*c)[2], (*c)[3]);
    return text;
}

}  // namespace

nlohmann::json pixel_history_json(const PixelReportInput& in) {
    const PixelHistory& h = *in.frame.find<PixelHistory>();
    nlohmann::json fragments = nlohmann::json::array();
    for (const PixelFragment& f : h.fragments) fragments.push_back(fragment_json(in, f));
    nlohmann::json settings = nlohmann::json::object();
    for (const auto& [name, value] : in.settings.values()) settings[name] = value;
    const DepthResult& d = *in.frame.depth;
    return {{"pixel", {h.x, h.y}},
            {"scene", in.scene.name},
            {"size", {in.frame.width, in.frame.height}},
            {"settings", settings},
            {"depth",
             {{"format", format::name(d.format)},
              {"reverse_z", d.reverse_z},
              {"znear", d.znear},
              {"zfar", d.zfar}}},
            {"final_color", final_color(in.frame, h)},
            {"dropped_records", h.dropped},
            {"gpu_ms",
             {{"replays", replay_and_frame_ms(in.frame).first},
              {"frame_passes", replay_and_frame_ms(in.frame).second}}},
            {"fragments", fragments}};
}

std::string pixel_history_table(const PixelReportInput& in) {
    const PixelHistory& h = *in.frame.find<PixelHistory>();
    std::string out;
    char line[512];
    std::snprintf(line, sizeof line, "pixel %u,%u of %s at %ux%u: %zu fragments\n", h.x, h.y,
                  in.scene.name.c_str(), in.frame.width, in.frame.height, h.fragments.size());
    out += line;
    if (h.fragments.empty()) out += "no fragment covered it\n";
    std::snprintf(line, sizeof line,
                  "%-3s %-14s %-4s %-24s %-5s %-3s %-11s %-9s %-5s %-11s %-13s %-6s %s\n", "#",
                  "pass", "draw", "mesh / material", "prim", "smp", "depth", "linear", "test",
                  "against", "alpha/cutoff", "shaded", "color (blended)");
    const std::string header = line;
    for (size_t i = 0; i < h.fragments.size(); ++i) {
        const PixelFragment& f = h.fragments[i];
        if (i == 0) out += header;
        const SurfaceName name = in.scene.instance_name(f.instance);
        char alpha[32] = "-";
        if (f.alpha_test)
            std::snprintf(alpha, sizeof alpha, "%.3f/%.3f %s", f.alpha_test->alpha,
                          f.alpha_test->cutoff, f.alpha_test->passed ? "ok" : "cut");
        std::string color = rgba_text(f.color);
        if (f.blended) color += " (" + rgba_text(f.blended) + ")";
        std::snprintf(
            line, sizeof line,
            "%-3zu %-14s %-4u %-24s %-5u %-3u %-11.9f %-9.4f %-5s %-11.9f %-13s %-6s %s\n", i,
            f.pass.c_str(), f.draw, (name.mesh + " / " + name.material).c_str(), f.primitive,
            f.sample, f.depth, linear(in.frame, f.depth), f.depth_passed ? "pass" : "fail",
            f.against, alpha, f.shaded ? "yes" : "no", color.c_str());
        out += line;
    }
    if (h.dropped) out += "warning: " + std::to_string(h.dropped) + " records dropped\n";
    const auto [replay, own] = replay_and_frame_ms(in.frame);
    std::snprintf(line, sizeof line, "replays %.2f ms GPU, the frame's own passes %.2f ms\n",
                  replay, own);
    return out + line;
}

}  // namespace ds::capture
