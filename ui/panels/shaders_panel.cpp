// Shaders: reload now, reload automatically when a file changes; a compile error shows as
// file:line while the last good pipelines keep running.
#include <imgui.h>

#include "ui/panels/panels.h"

namespace ds::ui {

void help_marker(const char* text) {
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

void shaders_panel(PanelIo& io) {
    const Inspector& in = io.inspector;
    if (ImGui::Button("Reload")) io.actions.push_back(ReloadShaders{});
    ImGui::SameLine();
    bool automatic = in.auto_reload();
    if (ImGui::Checkbox("when files change", &automatic))
        io.actions.push_back(SetAutoReload{automatic});
    ImGui::PushTextWrapPos(0.0f);
    if (in.shader_error())
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", in.shader_status().c_str());
    else
        ImGui::TextDisabled("%s", in.shader_status().c_str());
    ImGui::PopTextWrapPos();
}

}  // namespace ds::ui
