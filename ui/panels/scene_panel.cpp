// Scene: the built-in scenes, a .gltf / .glb by path (a bad file shows its error and the
// current scene stays), and what the scene holds.
#include <cstdio>
#include <map>
#include <string>

#include <imgui.h>

#include "renderer/scene/builtin/builtin.h"
#include "renderer/settings/frame_knobs.h"
#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

// One slider per MASK material: its alpha cutoff through material_alpha_cutoff (which wins
// over alpha_cutoff); right-click a slider to go back to the material's own value.
void masked_cutoffs(PanelIo& io, const SceneSummary& s) {
    if (s.masked_materials.empty()) return;
    const Settings& settings = io.inspector.settings();
    const auto overrides = knob_value(settings, knobs::kMaterialAlphaCutoff);
    const std::optional<float> global = knob_value(settings, knobs::kAlphaCutoff);
    ImGui::TextDisabled("alpha cutoff per masked material (right-click: the material's own)");
    int id = 0;
    for (const SceneSummary::Masked& m : s.masked_materials) {
        ImGui::PushID(id++);                          // material names need not be unique
        if (m.name.find(',') != std::string::npos) {  // the list could not name it
            ImGui::TextDisabled("%s: a ',' in the name: use alpha_cutoff", m.name.c_str());
            ImGui::PopID();
            continue;
        }
        const auto it = overrides.find(m.name);
        float v = it != overrides.end() ? it->second : global.value_or(m.own_cutoff);
        ImGui::SetNextItemWidth(-120);
        if (ImGui::SliderFloat(m.name.c_str(), &v, 0.0f, 1.0f, "%.3f")) {
            auto changed = overrides;
            changed[m.name] = v;
            io.actions.push_back(SetSetting{knobs::kMaterialAlphaCutoff.name, format_map(changed)});
        }
        if (ImGui::IsItemClicked(ImGuiMouseButton_Right) && it != overrides.end()) {
            auto changed = overrides;
            changed.erase(m.name);
            io.actions.push_back(SetSetting{knobs::kMaterialAlphaCutoff.name, format_map(changed)});
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s: own %.3f%s", m.name.c_str(), m.own_cutoff,
                              it != overrides.end() ? ", overridden" : "");
        ImGui::PopID();
    }
}

// The coplanar overlays classified at load and what each lies on (report.json "decals").
void decal_list(const scene::Scene& s) {
    if (s.decals.empty()) return;
    if (!ImGui::TreeNode("decals", "%zu coplanar overlays (decals)", s.decals.size())) return;
    for (const scene::Decal& d : s.decals)
        ImGui::BulletText("%s (%s) on %s", s.instances[d.instance].node.c_str(),
                          scene::to_string(s.instance_material(d.instance).alpha_mode),
                          s.instances[d.base].node.c_str());
    ImGui::TreePop();
}

// Overlays hidden just behind a surface facing the same way (scene/decals.h; diagnose's
// DECAL_BURIED): open by default, they are what a user loading a compressed file needs to see.
void buried_list(const scene::Scene& s) {
    if (s.buried.empty()) return;
    ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    if (!ImGui::TreeNode("buried", "%zu buried overlays (hidden)", s.buried.size())) return;
    for (const scene::BuriedOverlay& b : s.buried)
        ImGui::BulletText("%s %.3g mm behind %s", s.instances[b.instance].node.c_str(),
                          b.gap * 1000.0, s.instances[b.base].node.c_str());
    ImGui::TreePop();
}

}  // namespace

void scene_panel(PanelIo& io) {
    const SceneSummary& s = io.inspector.scene_summary();
    if (ImGui::BeginCombo("built-in", s.source.rfind("builtin:", 0) == 0 ? s.name.c_str() : "")) {
        for (const scene::builtin::Info& info : scene::builtin::list()) {
            if (ImGui::Selectable(info.name.c_str(), info.name == s.name))
                io.actions.push_back(LoadScene{info.name});
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", info.description.c_str());
        }
        ImGui::EndCombo();
    }
    auto& buffer = io.inspector.panel_state().scene_path;  // outlives the frame
    char* path = buffer.data();
    ImGui::SetNextItemWidth(-60);
    const bool enter = ImGui::InputTextWithHint("##path", ".gltf / .glb path", path, buffer.size(),
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && path[0]) io.actions.push_back(LoadScene{path});
    ImGui::Separator();
    ImGui::Text("%s", s.source.c_str());
    ImGui::Text("%s, %s, %s", counted(s.draw_groups, "draw group", "draw groups").c_str(),
                counted(s.instances, "instance", "instances").c_str(),
                counted(s.meshes, "mesh", "meshes").c_str());
    ImGui::TextUnformatted(counted(s.triangles, "triangle", "triangles").c_str());
    ImGui::Text("materials: %zu opaque, %zu masked, %zu blend", s.opaque, s.masked, s.blend);
    decal_list(io.inspector.scene());
    buried_list(io.inspector.scene());
    masked_cutoffs(io, s);
}

}  // namespace ds::ui
