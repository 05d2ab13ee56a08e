// EARLY_Z_LOST (warning): a pipeline that drew this frame and whose fragment shader runs before
// the depth test (discard, a depth or sample-mask write, storage writes, alpha to coverage:
// shader::early_z_verdict), so hidden fragments of its draws are shaded. The verdicts come from
// a frame of the user's settings alone (counting variants have verdicts of their own); what
// its draws shaded, showed and discarded from the measuring frame's per-draw counts.
#include <algorithm>

#include "capture/diagnose/checks.h"
#include "capture/diagnose/finding_json.h"
#include "renderer/passes/draw_counts.h"

namespace ds::diagnose {
namespace {

constexpr size_t kMaxNamedDraws = 10;

// The alpha modes a pipeline draws, from its role in the name (the passes' pipeline_name()):
// "<pass> unsplit" and "forward prepass" draw opaque and masked geometry, "... mask" masked,
// "... blend" and "transparent" blended, anything else opaque.
std::vector<std::string> drawn_alpha_modes(const std::string& pipeline) {
    const auto has = [&](const char* word) { return pipeline.find(word) != std::string::npos; };
    if (has(" prepass mask")) return {"mask"};
    if (has(" unsplit") || pipeline.starts_with("forward prepass")) return {"opaque", "mask"};
    if (has(" mask")) return {"mask"};
    if (has(" blend") || pipeline.starts_with("transparent")) return {"blend"};
    return {"opaque"};
}

// What one pass's draws of those alpha modes did in the measuring frame.
struct DrawShare {
    std::vector<const DrawReport*> draws;  // most shaded first
    uint64_t shaded = 0, visible = 0;
    bool visible_known = true;
    std::vector<uint32_t> pixels;
};

uint64_t shaded_in(const DrawReport& d, const std::string& pass) {
    for (const auto& [name, n] : d.shaded_fragments)
        if (name == pass) return n;
    return 0;
}

DrawShare share_of(const DrawsResult& draws, const std::string& pass,
                   const std::vector<std::string>& modes) {
    DrawShare s;
    std::vector<bool> in_share(draws.draws.size() + 1, false);
    for (const DrawReport& d : draws.draws) {
        const uint64_t shaded = shaded_in(d, pass);
        if (shaded == 0 || std::find(modes.begin(), modes.end(), d.alpha_mode) == modes.end())
            continue;
        s.draws.push_back(&d);
        s.shaded += shaded;
        if (d.visible_pixels)
            s.visible += *d.visible_pixels;
        else
            s.visible_known = false;
        if (d.group + 1 < in_share.size()) in_share[d.group + 1] = true;
    }
    for (uint32_t i = 0; i < draws.draw_pixels.size(); ++i)
        if (draws.draw_pixels[i] < in_share.size() && in_share[draws.draw_pixels[i]])
            s.pixels.push_back(i);
    std::stable_sort(s.draws.begin(), s.draws.end(), [&](const DrawReport* a, const DrawReport* b) {
        return shaded_in(*a, pass) > shaded_in(*b, pass);
    });
    return s;
}

std::string early_z_fix(const std::string& pipeline, const std::string& reasons) {
    if (pipeline.find(" unsplit") != std::string::npos)
        return "masked_split=on: opaque geometry in a pipeline without discard keeps early-Z; "
               "only MASK materials pay";
    if (reasons.find("discard") != std::string::npos)
        return "keep MASK materials few and drawn after opaque (so more of them fail the late "
               "test cheaply); with msaa > 1 alpha_to_coverage=on replaces the discard";
    return "remove " + reasons +
           " from the fragment shader, or give the draws that need it "
           "a pipeline of their own";
}

// What the pipeline's draws did in the measuring frame (`measured`: its pass there), into the
// message, magnitude, surfaces and pixels of `f`.
void add_draw_share(const CheckInput& in, const PassResult& measured, const PipelineReport& p,
                    Finding& f, std::string& message) {
    const DrawsResult& draws = passes::draws_of(in.measured);
    if (draws.draws.empty()) return;
    const DrawShare s = share_of(draws, measured.name, drawn_alpha_modes(p.name));
    message += ", " + grouped(double(s.shaded)) + " fragments shaded";
    f.magnitude = {double(s.shaded), "fragments"};
    if (s.visible_known && measured.draw_shaded_in_view) {
        message += " for " + grouped(double(s.visible)) + " visible px";
        f.magnitude = {double(s.shaded > s.visible ? s.shaded - s.visible : 0), "fragments"};
    }
    for (size_t i = 0; i < s.draws.size() && i < kMaxNamedDraws; ++i)
        f.surfaces.push_back(surface_of(in.scene, s.draws[i]->first_instance));
    if (measured.draw_shaded_in_view) f.pixels = s.pixels;
}

Finding early_z_finding(const CheckInput& in, const PassResult& pass, const PipelineReport& p) {
    const std::string reasons =
        p.early_z.substr(std::min<size_t>(p.early_z.size(), 6));  // "lost: "
    Finding f;
    f.code = "EARLY_Z_LOST";
    f.severity = Severity::Warning;
    f.detector = "early_z";
    f.fix = early_z_fix(p.name, reasons);
    f.magnitude = {double(p.draws), "draws"};
    std::string message = p.name + " loses early-Z (" + reasons + "): " + grouped(double(p.draws)) +
                          (p.draws == 1 ? " draw" : " draws");
    const PassResult* measured = pass_named(in.measured, pass.name);
    if (measured) add_draw_share(in, *measured, p, f, message);
    if (measured && measured->discarded_fragments && reasons.find("discard") != std::string::npos)
        message += ", " + grouped(double(*measured->discarded_fragments)) + " discarded";
    const bool in_view = !measured || measured->draw_shaded_in_view;
    f.message = message + " (" + pass.name + (in_view ? ")" : ": the light's view)");
    if (!f.surfaces.empty()) f.pointer = f.surfaces.front().pointer;
    return f;
}

}  // namespace

void check_early_z(const CheckInput& in, CheckOutput& out) {
    const FrameResult& verdicts = in.plain ? *in.plain : in.measured;
    out.ran.push_back("early_z");
    for (const PassResult& pass : verdicts.passes) {
        if (pass.role != graph::PassRole::Frame || pass.name == "zfight") continue;
        for (const PipelineReport& p : pass.pipelines)
            if (p.draws > 0 && p.early_z.starts_with("lost"))
                out.findings.push_back(early_z_finding(in, pass, p));
    }
}

}  // namespace ds::diagnose
