// Depth: what the Z-fighting diagnostics found this frame. zfight's pairs of surfaces (mesh,
// material, node; pixels and the smallest gap in depth steps) and equal_check's holes and
// ties with the surfaces involved; a click shows the image behind them. When a diagnostic is
// off, one button turns it on; when the frame left it out, the report's reason.
#include <cstdio>
#include <string>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

std::string surface_text(const SurfaceName& s) {
    return s.node + " (" + s.mesh + ", " + s.material + ")";
}

// "on" button, or why the frame skipped it; true when the diagnostic has results to show.
bool diagnostic_state(PanelIo& io, const char* knob, bool has_results) {
    if (has_results) return true;
    const Inspector& in = io.inspector;
    if (in.settings().get(knob) != "on") {
        ImGui::TextDisabled("%s is off", knob);
        ImGui::SameLine();
        ImGui::PushID(knob);
        if (ImGui::SmallButton("turn on")) io.actions.push_back(SetSetting{knob, "on"});
        ImGui::PopID();
        return false;
    }
    for (const std::string& s : in.frame().skipped)
        if (s.rfind(std::string(knob) + ":", 0) == 0) ImGui::TextDisabled("%s", s.c_str());
    return false;
}

void zfight_section(PanelIo& io) {
    const FrameResult& frame = io.inspector.frame();
    if (!diagnostic_state(io, "zfight", frame.zfight.has_value())) return;
    const ZfightResult& z = *frame.zfight;
    ImGui::Text("%llu pixels fight, %zu pairs (gap <= %u steps)",
                static_cast<unsigned long long>(z.pixels), z.pairs.size(), z.steps);
    if (ImGui::SmallButton("view zfight")) io.actions.push_back(SelectResource{"zfight"});
    ImGui::SameLine();
    if (ImGui::SmallButton("view surface_id")) io.actions.push_back(SelectResource{"surface_id"});
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollY;
    if (z.pairs.empty() || !ImGui::BeginTable("pairs", 4, flags, ImVec2(0, 110))) return;
    ImGui::TableSetupColumn("a");
    ImGui::TableSetupColumn("b");
    ImGui::TableSetupColumn("pixels");
    ImGui::TableSetupColumn("min steps");
    ImGui::TableHeadersRow();
    for (size_t i = 0; i < z.pairs.size(); ++i) {
        const ZfightPair& p = z.pairs[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        // Selecting a pair shows only its pixels in the zfight view; again: all of them.
        const bool selected = io.viewer.zfight_pair == int(i);
        ImGui::PushID(int(i));
        if (ImGui::Selectable(surface_text(p.a).c_str(), selected,
                              ImGuiSelectableFlags_SpanAllColumns)) {
            io.viewer.zfight_pair = selected ? -1 : int(i);
            io.actions.push_back(SelectResource{"zfight"});
        }
        ImGui::PopID();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(surface_text(p.b).c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%llu", static_cast<unsigned long long>(p.pixels));
        ImGui::TableNextColumn();
        ImGui::Text("%u", p.min_steps);
    }
    ImGui::EndTable();
}

void equal_check_section(PanelIo& io) {
    const FrameResult& frame = io.inspector.frame();
    if (!diagnostic_state(io, "equal_check", frame.equal_check.has_value())) return;
    const EqualCheckResult& e = *frame.equal_check;
    ImGui::Text("%llu holes, %llu pixels shaded more than once",
                static_cast<unsigned long long>(e.holes),
                static_cast<unsigned long long>(e.multiple));
    if (ImGui::SmallButton("view equal_check")) io.actions.push_back(SelectResource{"equal_check"});
    for (const EqualCheckSurface& s : e.surfaces)
        ImGui::BulletText("%s: %llu holes, %llu ties", surface_text(s.name).c_str(),
                          static_cast<unsigned long long>(s.holes),
                          static_cast<unsigned long long>(s.multiple));
}

}  // namespace

void depth_panel(PanelIo& io, const PanelLayout& layout) {
    // Below the Resources panel, collapsed until wanted: the diagnostics cost frames.
    ImGui::SetNextWindowPos(ImVec2(layout.left(), layout.height * 0.6f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(
        ImVec2(layout.width - layout.left() - layout.right(), layout.height * 0.4f),
        ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Depth")) {
        ImGui::End();
        return;
    }
    if (ImGui::CollapsingHeader("Z-fighting", ImGuiTreeNodeFlags_DefaultOpen)) zfight_section(io);
    if (ImGui::CollapsingHeader("EQUAL check", ImGuiTreeNodeFlags_DefaultOpen))
        equal_check_section(io);
    ImGui::End();
}

}  // namespace ds::ui
