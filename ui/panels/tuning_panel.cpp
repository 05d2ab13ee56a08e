// Tuning: MSAA and alpha cutoff scored against a supersampled reference of the current view
// (capture/tune/, what `depthscope tune msaa|alpha` prints): the candidates' table and plot,
// the Pareto front, and an Apply button for each recommendation, which sets its knobs.
#include <imgui.h>

#include "capture/tune/tune_report.h"
#include "ui/panels/panels.h"
#include "ui/panels/plot_widget.h"

namespace ds::ui {
namespace {

void apply_button(PanelIo& io, const char* id, const std::vector<std::string>& assignments) {
    ImGui::PushID(id);
    if (ImGui::SmallButton("Apply"))
        for (const std::string& a : assignments) {
            const size_t eq = a.find('=');
            io.actions.push_back(SetSetting{a.substr(0, eq), a.substr(eq + 1)});
        }
    ImGui::PopID();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", tune::assignments_text(assignments).c_str());
}

void run_line(PanelIo& io, int& cost) {
    const Tuning& t = io.inspector.tuning();
    ImGui::BeginDisabled(t.running());
    const tune::CostKind kind = cost == 1 ? tune::CostKind::Ms : tune::CostKind::Fragments;
    if (ImGui::Button("Score MSAA settings")) io.actions.push_back(Tune{TuneKind::Msaa, kind});
    ImGui::SameLine();
    if (ImGui::Button("Sweep alpha cutoffs")) io.actions.push_back(Tune{TuneKind::Alpha, kind});
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(140);
    ImGui::Combo("cost", &cost, "shaded fragments\0GPU ms\0");
    ImGui::SameLine();
    if (t.running())
        ImGui::TextDisabled("tuning... %.0f s (the view keeps its last frame)", t.seconds());
    else
        help_marker(
            "Renders a reference of this view at 4x4 samples per pixel (every sample "
            "shaded, alpha tested at full resolution, box-resolved in linear HDR; gtao "
            "and contact_shadows off here and in every candidate), then each candidate, "
            "and scores it: SSIM and the mean luma error on edge pixels (MSAA), the "
            "share of a MASK material's pixels covered differently (alpha).");
    if (!t.error().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", t.error().c_str());
}

void msaa_section(PanelIo& io, const tune::MsaaTune& t) {
    ImGui::Text("MSAA at %ux%u: reference %.1f s, %llu edge pixels", t.size.width, t.size.height,
                t.reference_ms / 1000.0, (unsigned long long)t.edge_pixels);
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX;
    if (ImGui::BeginTable("msaa", 5, flags, ImVec2(table_fit_width("msaa"), 0))) {
        for (const char* h : {"candidate", "SSIM", "edge error", "cost", "front"})
            ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        for (const tune::MsaaRow& r : t.rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r.candidate.label().c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.5f", r.score.ssim);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", r.score.edge_error);
            ImGui::TableNextColumn();
            ImGui::Text("%.6g", r.cost.value(t.cost_kind));
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r.front ? "yes" : "");
        }
        ImGui::EndTable();
    }
    for (size_t i = 0; i < t.recommendations.size(); ++i) {
        const tune::Recommendation& rec = t.recommendations[i];
        if (rec.row < 0) continue;
        const tune::MsaaRow& r = t.rows[size_t(rec.row)];
        if (rec.budget > 0)
            ImGui::Text("within %.1fx the cheapest: %s", rec.budget, r.candidate.label().c_str());
        else
            ImGui::Text("any cost: %s", r.candidate.label().c_str());
        ImGui::SameLine();
        apply_button(io, ("msaa" + std::to_string(i)).c_str(), r.candidate.assignments());
    }
}

void alpha_section(PanelIo& io, const tune::AlphaTune& t) {
    ImGui::Text("Alpha at %ux%u, msaa %d", t.size.width, t.size.height, t.msaa);
    for (size_t i = 0; i < t.materials.size(); ++i) {
        const tune::AlphaMaterial& m = t.materials[i];
        if (m.best < 0) continue;
        const tune::AlphaPoint& b = m.points[size_t(m.best)];
        const double now = m.current >= 0 ? m.points[size_t(m.current)].coverage_error : -1.0;
        ImGui::Text("%s: cutoff %.3f (error %.3f) -> best %.3f%s (error %.3f)", m.name.c_str(),
                    m.cutoff, now, b.cutoff, b.alpha_to_coverage ? " + alpha_to_coverage" : "",
                    b.coverage_error);
        ImGui::SameLine();
        auto overrides = io.inspector.settings().get_map("material_alpha_cutoff");
        overrides[m.name] = b.cutoff;
        std::vector<std::string> set = {"material_alpha_cutoff=" + format_map(overrides)};
        if (t.msaa > 1)
            set.push_back(std::string("alpha_to_coverage=") + (b.alpha_to_coverage ? "on" : "off"));
        apply_button(io, ("alpha" + std::to_string(i)).c_str(), set);
    }
}

// The section's table and buttons on the left, its plot on the right.
template <class Left, class Right>
void side_by_side(const char* id, Left left, Right right) {
    if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_Resizable | ImGuiTableFlags_BordersInnerV))
        return;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    left();
    ImGui::TableNextColumn();
    right();
    ImGui::EndTable();
}

}  // namespace

void tuning_panel(PanelIo& io) {
    run_line(io, io.inspector.panel_state().tune_cost);
    const Tuning& t = io.inspector.tuning();
    if (t.msaa())
        side_by_side(
            "msaa_layout", [&] { msaa_section(io, *t.msaa()); },
            [&] { plot_widget("msaa_plot", tune::msaa_plot(*t.msaa()), 200.0f); });
    if (t.msaa() && t.alpha()) ImGui::Separator();
    if (t.alpha())
        side_by_side(
            "alpha_layout", [&] { alpha_section(io, *t.alpha()); },
            [&] { plot_widget("alpha_plot", tune::alpha_plot(*t.alpha()), 200.0f); });
    if (!t.msaa() && !t.alpha() && !t.running())
        ImGui::TextDisabled("Nothing scored yet: run one of the sweeps above.");
}

}  // namespace ds::ui
