// Pixel: the history of one pixel (PickPixel: the viewer's "pick" mouse mode or Alt + click),
// every fragment that covered it in submission order: pass, draw and surface, primitive and
// sample, depth raw and linear, the depth test against the value it met, the alpha test,
// whether the shader ran, the colour it wrote and, for blended passes, the colour after
// blending. Exact: from instrumented replays of the passes' own draws (pixel_history.h).
#include <cmath>
#include <string>

#include <imgui.h>

#include "renderer/settings/frame_knobs.h"
#include "renderer/view/decode.h"
#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

constexpr ImGuiTableFlags kTableFlags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                        ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX |
                                        ImGuiTableFlags_ScrollY;
// The history's columns and what each means (the headers' tooltips).
struct PixelColumn {
    const char* name;
    const char* help;
};
constexpr PixelColumn kColumns[] = {
    {"#", "the fragment's place in submission order"},
    {"pass", "the geometry pass that drew it (hover a row: its pipeline)"},
    {"draw", "the draw's index within its pass"},
    {"surface", "mesh / material (hover a row: node and instance)"},
    {"prim", "the primitive (triangle) within the draw"},
    {"smp", "the MSAA sample the fragment was tested at (0 without MSAA)"},
    {"depth", "the fragment's depth as stored (0..1; reverse-Z: 1 is near)"},
    {"linear", "its distance from the camera in scene units, from the frame's planes"},
    {"test", "the depth test against 'against': pass or fail"},
    {"against", "the depth buffer's value when the fragment was tested, as stored"},
    {"alpha",
     "masked materials: alpha / cutoff, and the alpha test's outcome (kept or "
     "discarded); '-': no alpha test"},
    {"shaded", "the fragment shader ran (early-Z pipelines: only if the depth test passed)"},
    {"colour", "the colour the shader wrote (HDR, shown tone-mapped; hover: the numbers)"},
    {"blended", "blended passes: the colour after blending with what was there"}};
constexpr int kAlphaColumn = 10;

// HDR colours as swatches: Reinhard per channel, so bright values still show their hue; the
// tooltip has the numbers.
void swatch(const char* id, const std::optional<std::array<float, 4>>& c) {
    if (!c) {
        ImGui::TextDisabled("-");
        return;
    }
    auto map = [](float v) { return std::isfinite(v) ? v / (1.0f + std::max(v, 0.0f)) : 1.0f; };
    const ImVec4 shown(map((*c)[0]), map((*c)[1]), map((*c)[2]), 1.0f);
    ImGui::ColorButton(id, shown, ImGuiColorEditFlags_NoTooltip, ImVec2(28, 14));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%.4f %.4f %.4f %.4f", (*c)[0], (*c)[1], (*c)[2], (*c)[3]);
}

void fragment_row(const Inspector& in, size_t i, const PixelFragment& f) {
    const DepthResult& d = *in.pixel_depth();
    const SurfaceName name = in.scene().instance_name(f.instance);
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::Text("%zu", i);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(f.pass.c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("pipeline: %s", f.pipeline.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%u", f.draw);
    ImGui::TableNextColumn();
    ImGui::Text("%s / %s", name.mesh.c_str(), name.material.c_str());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("node %s, instance %u", name.node.c_str(), f.instance);
    ImGui::TableNextColumn();
    ImGui::Text("%u", f.primitive);
    ImGui::TableNextColumn();
    ImGui::Text("%u", f.sample);
    ImGui::TableNextColumn();
    ImGui::Text("%.9f", f.depth);
    ImGui::TableNextColumn();
    ImGui::Text("%.4f", view::linear_depth(f.depth, d.reverse_z, d.znear, d.zfar));
    ImGui::TableNextColumn();
    const ImVec4 colour = f.depth_passed ? ImVec4(0.5f, 1, 0.5f, 1) : ImVec4(1, 0.5f, 0.4f, 1);
    ImGui::TextColored(colour, "%s", f.depth_passed ? "pass" : "fail");
    ImGui::TableNextColumn();
    ImGui::Text("%.9f", f.against);
    ImGui::TableNextColumn();
    if (f.alpha_test)
        ImGui::Text("%.3f / %.3f %s", f.alpha_test->alpha, f.alpha_test->cutoff,
                    f.alpha_test->passed ? "kept" : "discarded");
    else
        ImGui::TextDisabled("-");
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(f.shaded ? "yes" : "no");
    ImGui::TableNextColumn();
    swatch(("##c" + std::to_string(i)).c_str(), f.color);
    ImGui::TableNextColumn();
    swatch(("##b" + std::to_string(i)).c_str(), f.blended);
}

void history_table(const Inspector& in) {
    const PixelHistory& h = *in.pixel_history();
    ImGui::Text("pixel (%u, %u) of %s: %s", h.x, h.y, in.pixel_label().c_str(),
                counted(h.fragments.size(), "fragment", "fragments").c_str());
    if (h.dropped)
        ImGui::TextColored(ImVec4(1, 0.6f, 0.3f, 1), "%s dropped: the list is short",
                           counted(h.dropped, "record", "records").c_str());
    if (h.fragments.empty()) {
        ImGui::TextDisabled("no surface covered this pixel (the sky's)");
        return;
    }
    const int columns = int(std::size(kColumns));
    if (!ImGui::BeginTable("fragments", columns, kTableFlags, scrolling_table_size())) return;
    // The alpha column is as wide as its widest text: "discarded" and "kept" whole.
    const float alpha_width = ImGui::CalcTextSize("0.000 / 0.000 discarded").x;
    std::vector<std::string> help;
    for (int c = 0; c < columns; ++c) {
        const PixelColumn& column = kColumns[c];
        ImGui::TableSetupColumn(column.name, 0, c == kAlphaColumn ? alpha_width : 0.0f);
        help.push_back(column.help);
    }
    ImGui::TableSetupScrollFreeze(0, 1);
    header_row_with_help(help);
    for (size_t i = 0; i < h.fragments.size(); ++i) fragment_row(in, i, h.fragments[i]);
    ImGui::EndTable();
}

// The picked pixel's samples (msaa > 1) and, per prepass fragment, the samples it was
// rasterized to (gl_SampleMaskIn: before the alpha test or alpha to coverage) against those its
// triangle holds at the end of the frame (after alpha to coverage and every depth test).
void samples_section(const Inspector& in) {
    const std::optional<MsaaSamples>& samples = in.pixel_samples();
    const PixelHistory& h = *in.pixel_history();
    if (!samples || samples->samples < 2 || !in.pixel_depth()) return;
    if (!ImGui::CollapsingHeader("samples and coverage", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const std::optional<PixelSampleList> list =
        sample_list(*samples, h.x, h.y, *in.pixel_depth(), in.device().standard_sample_locations,
                    [&in](uint32_t id) { return in.describe_surface(id); });
    if (list) sample_table(*list);
    const std::vector<CoverageRow> rows = in.pixel_coverage();
    if (rows.empty()) return;
    const bool a2c = knob_value(in.settings(), knobs::kAlphaToCoverage);
    ImGui::SameLine();
    help_marker(
        "Per prepass triangle: 'rasterized' is its coverage before any alpha test "
        "(gl_SampleMaskIn, from the replay's per-sample records); 'kept' the samples its "
        "triangle holds at the end of the frame (the per-sample surface_id): with "
        "alpha_to_coverage on, a masked triangle's rasterized samples missing from "
        "'kept' were cut by its alpha, unless a nearer surface won them (see depth).");
    constexpr ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("coverage", 5, flags, ImVec2(table_fit_width("coverage"), 0))) return;
    for (const char* c : {"surface", "prim", "alpha", "rasterized (before)", "kept (after)"})
        ImGui::TableSetupColumn(c);
    ImGui::TableHeadersRow();
    for (const CoverageRow& r : rows) {
        const SurfaceName name = in.scene().instance_name(r.instance);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%s / %s", name.mesh.c_str(), name.material.c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%u", r.primitive);
        ImGui::TableNextColumn();
        if (r.alpha)
            ImGui::Text("%.3f%s", *r.alpha, a2c ? " (a2c)" : "");
        else
            ImGui::TextDisabled("opaque");
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(mask_text(r.rasterized, samples->samples).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(mask_text(r.kept, samples->samples).c_str());
    }
    ImGui::EndTable();
}

}  // namespace

bool pixel_panel_wants_tab(PanelIo& io) {
    Inspector::PanelState& state = io.inspector.panel_state();
    if (io.inspector.pixel_picks() == state.pixel_picks_shown) return false;
    state.pixel_picks_shown = io.inspector.pixel_picks();  // a new pick: show it
    return true;
}

void pixel_panel(PanelIo& io) {
    const Inspector& in = io.inspector;
    if (in.pixel_history()) {
        if (ImGui::Button("again")) {  // the same pixel with the settings as they are now
            io.actions.push_back(PickPixel{in.pixel_history()->x, in.pixel_history()->y});
        }
        ImGui::SameLine();
    }
    help_marker(
        "Every fragment that covered the pixel, in submission order, from instrumented replays "
        "of each geometry pass's own draws; the depth test, depth writes and blending are "
        "replayed on them in order. 'against' is the depth buffer's value when the fragment "
        "was tested; 'shaded': the fragment shader ran (early-Z pipelines: only if it passed).");
    if (!in.pixel_error().empty())
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", in.pixel_error().c_str());
    if (in.pixel_history() && in.pixel_depth()) {
        samples_section(in);
        history_table(in);
    } else
        ImGui::TextDisabled("pick a pixel: the viewer's \"pick\" mouse mode (or Alt) and a click");
}

}  // namespace ds::ui
