// Camera: where the camera is, the views to go to — frame the content (F), the scene's own
// camera, "fit inside" for interiors (scene/fit_inside.h), each of the scene's camera nodes —
// and named bookmarks of this scene's views (add the current one, go to one, delete one),
// kept in the config folder with the inspector's other state (ui/config.h: cameras.json).
#include <cstdio>

#include <imgui.h>

#include "renderer/scene/fit_inside.h"
#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

const ImVec4 kBookmarkError(1, 0.4f, 0.4f, 1);

// A note in the disabled colour, wrapped to the tab's width (the left column is narrow).
void note(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

void where(const scene::Camera& c) {
    ImGui::Text("at %.3g, %.3g, %.3g", double(c.position.x), double(c.position.y),
                double(c.position.z));
    ImGui::Text("looking %.2f, %.2f, %.2f", double(c.forward.x), double(c.forward.y),
                double(c.forward.z));
    ImGui::Text("fov %.1f deg, planes %.3g..%.3g", double(glm::degrees(c.yfov)), double(c.znear),
                double(c.zfar));
}

void views(PanelIo& io) {
    if (ImGui::Button("frame")) io.camera.frame = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The scene's content from outside (F).");
    ImGui::SameLine();
    if (ImGui::Button("scene camera")) io.actions.push_back(SceneCamera{});
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The scene's own camera (or the one the command line chose).");
    ImGui::SameLine();
    if (ImGui::Button("fit inside")) io.actions.push_back(FitInside{});
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "For interiors: the camera at an open spot inside the scene's bounds (the centre, "
            "%.1f above the floor there), looking along their longest horizontal axis.",
            double(scene::kEyeHeight));
}

// The scene's camera nodes, as `depthscope cameras` lists them and --camera picks them.
void scene_cameras(PanelIo& io) {
    const std::vector<scene::SceneCamera>& cameras = io.inspector.scene().cameras;
    if (cameras.empty()) {
        note("the scene has no camera nodes");
        return;
    }
    note("the scene's camera nodes (--camera INDEX|NAME):");
    for (size_t i = 0; i < cameras.size(); ++i) {
        const scene::SceneCamera& c = cameras[i];
        ImGui::PushID(int(i));
        const std::string label = std::to_string(i) + " " + (c.name.empty() ? "(unnamed)" : c.name);
        if (c.camera) {
            if (ImGui::SmallButton("go")) io.actions.push_back(GoToCamera{i});
            ImGui::SameLine();
            ImGui::Text("%s, fov %.1f deg", label.c_str(), double(glm::degrees(c.yfov)));
        } else {
            ImGui::TextDisabled("%s: %s", label.c_str(),
                                c.type == scene::SceneCamera::Type::Orthographic
                                    ? "orthographic (not supported)"
                                    : "no view direction");
        }
        ImGui::PopID();
    }
}

}  // namespace

void bookmark_list(PanelIo& io) {
    const Inspector& in = io.inspector;
    std::array<char, 128>& name = in.panel_state().bookmark_name;
    note("bookmarks of this scene:");
    ImGui::SetNextItemWidth(180);
    const bool enter = ImGui::InputTextWithHint("##bookmark", "name", name.data(), name.size(),
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("add") || enter) && name[0]) {
        io.actions.push_back(AddBookmark{name.data()});
        name[0] = '\0';  // ready for the next one
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The current camera under this name (one of the same name is replaced).");
    for (const CameraBookmark& b : in.scene_bookmarks()) {
        ImGui::PushID(b.name.c_str());
        if (ImGui::SmallButton("go")) io.actions.push_back(GoToBookmark{b.name});
        ImGui::SameLine();
        if (ImGui::SmallButton("delete")) io.actions.push_back(DeleteBookmark{b.name});
        ImGui::SameLine();
        ImGui::TextUnformatted(b.name.c_str());
        ImGui::PopID();
    }
    if (in.scene_bookmarks().empty()) note("none yet");
    const CameraBookmarks& all = in.bookmarks();
    if (!all.error().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kBookmarkError);
        ImGui::TextWrapped("%s", all.error().c_str());
        ImGui::PopStyleColor();
    } else {
        note(all.file().empty() ? "kept for this session only" : "kept in " + all.file().string());
    }
}

void camera_panel(PanelIo& io) {
    where(io.inspector.camera());
    views(io);
    ImGui::Separator();
    scene_cameras(io);
    ImGui::Separator();
    bookmark_list(io);
}

}  // namespace ds::ui
