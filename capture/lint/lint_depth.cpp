// The depth facts lint's checks share: the user's depth configuration per view, and where two
// parallel surfaces a gap apart start to fight in each format (view/precision.h's model).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "capture/lint/checks.h"
#include "renderer/settings/frame_knobs.h"

namespace ds::lint {
namespace {

constexpr int kFightSamples = 4096;  // log-spaced depths between the planes

uint32_t format_bits(const std::string& format) {
    return format == "d16" ? 16u : format == "d24" ? 24u : 32u;
}

}  // namespace

view::DepthConfig depth_config(const Settings& settings, const scene::Camera& camera) {
    view::DepthConfig c;
    c.bits = format_bits(knob_value(settings, knobs::kDepthFormat));
    c.reverse_z = knob_value(settings, knobs::kReverseZ);
    c.znear = knob_value(settings, knobs::kZnear).value_or(camera.znear);
    c.zfar = knob_value(settings, knobs::kZfar).value_or(camera.zfar);
    return c;
}

std::string depth_name(const view::DepthConfig& c) {
    if (c.bits != 32) return "d" + std::to_string(c.bits);
    return c.reverse_z ? "d32f reverse-Z" : "d32f forward-Z";
}

std::vector<view::DepthConfig> every_format(const view::DepthConfig& planes) {
    std::vector<view::DepthConfig> out;
    for (const auto& [bits, reverse] :
         {std::pair{32u, true}, {32u, false}, {24u, false}, {16u, false}})
        out.push_back({bits, reverse, planes.znear, planes.zfar});
    return out;
}

std::optional<double> fight_distance(const view::DepthConfig& c, double gap, double seen_to) {
    const double far = std::min(c.zfar, seen_to);
    if (!(c.znear > 0 && far > c.znear)) return std::nullopt;
    const double ln = std::log(c.znear), lf = std::log(far);
    double below = c.znear;  // a depth whose step is below the gap
    if (view::step_at(c, c.znear) >= gap) return c.znear;
    for (int i = 1; i <= kFightSamples; ++i) {
        const double z = i == kFightSamples ? far : std::exp(ln + (lf - ln) * i / kFightSamples);
        if (view::step_at(c, z) < gap) {
            below = z;
            continue;
        }
        double lo = below, hi = z;  // step(lo) < gap <= step(hi)
        for (int k = 0; k < 60; ++k) {
            const double mid = 0.5 * (lo + hi);
            (view::step_at(c, mid) >= gap ? hi : lo) = mid;
        }
        return hi;
    }
    return std::nullopt;
}

double coarsest_step(const view::DepthConfig& c, double seen_to) {
    const double far = std::min(c.zfar, seen_to);
    if (!(c.znear > 0 && far > c.znear)) return 0.0;
    const double ln = std::log(c.znear), lf = std::log(far);
    double coarsest = 0.0;
    for (int i = 0; i < kFightSamples; ++i)
        coarsest = std::max(coarsest,
                            view::step_at(c, std::exp(ln + (lf - ln) * (i + 0.5) / kFightSamples)));
    return coarsest;
}

double seen_to(const scene::Scene& scene, const scene::Camera& camera) {
    const scene::Bounds& b = scene.bounds;
    if (!b.valid()) return 0.0;
    double farthest = 0.0;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                               (i & 4) ? b.max.z : b.min.z);
        farthest = std::max(farthest, double(glm::length(corner - camera.position)));
    }
    return farthest;
}

std::string g3(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

}  // namespace ds::lint
