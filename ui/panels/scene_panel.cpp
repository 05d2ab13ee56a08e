// Scene: the built-in scenes, a .gltf / .glb by path (a bad file shows its error and the
// current scene stays), and what the scene holds.
#include <cstdio>

#include <imgui.h>

#include "renderer/scene/builtin/builtin.h"
#include "ui/panels/panels.h"

namespace ds::ui {

void scene_panel(PanelIo& io, const PanelLayout& layout) {
    ImGui::SetNextWindowPos(ImVec2(0, layout.height * 0.55f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(PanelLayout::kLeft, layout.height * 0.27f),
                             ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Scene")) {
        ImGui::End();
        return;
    }
    const SceneSummary& s = io.inspector.scene_summary();
    if (ImGui::BeginCombo("built-in", s.source.rfind("builtin:", 0) == 0 ? s.name.c_str() : "")) {
        for (const scene::builtin::Info& info : scene::builtin::list()) {
            if (ImGui::Selectable(info.name.c_str(), info.name == s.name))
                io.actions.push_back(LoadScene{info.name});
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", info.description.c_str());
        }
        ImGui::EndCombo();
    }
    static char path[512] = "";
    ImGui::SetNextItemWidth(-60);
    const bool enter = ImGui::InputTextWithHint("##path", ".gltf / .glb path", path, sizeof path,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && path[0]) io.actions.push_back(LoadScene{path});
    ImGui::Separator();
    ImGui::Text("%s", s.source.c_str());
    ImGui::Text("%zu draw groups, %zu instances, %zu meshes", s.draw_groups, s.instances, s.meshes);
    ImGui::Text("%llu triangles", static_cast<unsigned long long>(s.triangles));
    ImGui::Text("materials: %zu opaque, %zu masked, %zu blend", s.opaque, s.masked, s.blend);
    ImGui::End();
}

}  // namespace ds::ui
