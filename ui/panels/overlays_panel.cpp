// Overlays: images drawn over the viewer's, several at once — count images (a pass's shaded,
// discarded, rasterized, its derived wasted view), surface_id, zfight, equal_check,
// depth_precision, any image of the frame. Each is decoded as the viewer would show it
// (counts as a heat map on its pass's shared scale) and blended with its opacity where its
// value is not 0, in list order (the last on top). The list is view state: opacity and
// visibility are written directly; adding, removing and reordering are actions, so the list
// does not change under the loop that draws it.
#include <algorithm>
#include <string>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

constexpr const char* kOverlayBase = "final";  // the base an overlay goes over, not one itself

constexpr const char* kSharedHelp =
    "Count images of one pass (<pass>_counts = shaded, _discarded, _rasterized, _wasted) use "
    "one heat scale, 0 to the largest count over all of them, so a colour means the same "
    "number in each; the viewer draws one legend per pass. Off: each image fits its own "
    "range. A manual black / white range in the viewer is shared too.";

bool listed(const std::vector<Overlay>& overlays, const std::string& name) {
    return std::any_of(overlays.begin(), overlays.end(),
                       [&](const Overlay& o) { return o.resource == name; });
}

// The "add" picker: the frame's images and derived views not in the list yet.
void add_picker(PanelIo& io) {
    ImGui::SetNextItemWidth(200);
    if (!ImGui::BeginCombo("##add", "add an overlay")) return;
    for (const std::string& name : io.inspector.viewable()) {
        if (name == kOverlayBase || listed(io.viewer.overlays, name)) continue;
        if (ImGui::Selectable(name.c_str(), false)) io.actions.push_back(AddOverlay{name});
    }
    ImGui::EndCombo();
}

// One overlay's row: visible, opacity, up / down, remove, its name and why it is not drawn.
void overlay_row(PanelIo& io, size_t i, const std::string& status) {
    Overlay& o = io.viewer.overlays[i];
    ImGui::PushID(int(i));
    ImGui::Checkbox("##visible", &o.visible);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(130);
    ImGui::SliderFloat("##opacity", &o.opacity, 0.0f, 1.0f, "opacity %.2f");
    ImGui::SameLine();
    if (ImGui::SmallButton("up")) io.actions.push_back(MoveOverlay{i, -1});
    ImGui::SameLine();
    if (ImGui::SmallButton("down")) io.actions.push_back(MoveOverlay{i, +1});
    ImGui::SameLine();
    if (ImGui::SmallButton("remove")) io.actions.push_back(RemoveOverlay{i});
    ImGui::SameLine();
    ImGui::TextUnformatted(o.resource.c_str());
    if (!status.empty()) {
        ImGui::SameLine();
        ImGui::TextDisabled("(%s)", status.c_str());
    }
    ImGui::PopID();
}

}  // namespace

void overlays_panel(PanelIo& io) {
    add_picker(io);
    ImGui::SameLine();
    ImGui::Checkbox("one scale per pass", &io.viewer.shared_count_scale);
    ImGui::SameLine();
    help_marker(kSharedHelp);
    const std::vector<std::string>& status = io.inspector.composer().overlay_status();
    for (size_t i = 0; i < io.viewer.overlays.size(); ++i)
        overlay_row(io, i, i < status.size() ? status[i] : std::string());
    if (io.viewer.overlays.empty())
        ImGui::TextDisabled(
            "no overlays: add an image to draw it over the viewer's (0 = transparent)");
}

}  // namespace ds::ui
