// The workspace drawn (workspace.h): one window over the whole display, without background or
// decoration; its splitters between the regions; each region a child window with the panel
// colour, a tab bar and the open tab's panel in a scrolling child; the viewer's region last.
#include <algorithm>

#include <imgui.h>
#include <imgui_internal.h>  // SplitterBehavior, MarkIniSettingsDirty

#include "ui/panels/panels.h"
#include "ui/panels/workspace.h"

namespace ds::ui {
namespace {

constexpr ImGuiWindowFlags kHostFlags =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
    ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoScrollWithMouse |
    ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoNavFocus;
constexpr ImGuiWindowFlags kRegionFlags = ImGuiWindowFlags_AlwaysUseWindowPadding |
                                          ImGuiWindowFlags_NoScrollbar |
                                          ImGuiWindowFlags_NoScrollWithMouse;
constexpr ImGuiWindowFlags kViewerFlags =
    ImGuiWindowFlags_AlwaysUseWindowPadding | ImGuiWindowFlags_NoBackground |
    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse;

// One splitter: `a` and `b` are the sizes on either side, each kept at its minimum (or what
// it has, if less: a small window). True while dragged and changed.
bool splitter(const char* id, const ImRect& bb, ImGuiAxis axis, float& a, float& b, float min_a,
              float min_b) {
    const float before = a;
    ImGui::SplitterBehavior(bb, ImGui::GetID(id), axis, &a, &b, std::min(min_a, a),
                            std::min(min_b, b), /*hover_extend=*/2.0f);
    return a != before;
}

Rect item_rect() {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    return {a.x, a.y, b.x - a.x, b.y - a.y};
}

}  // namespace

void Workspace::draw(PanelIo& io) {
    for (const PanelEntry& p : panel_list())
        if (p.wants_tab && p.wants_tab(io)) select(p.name);
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    layout_ = layout(wanted_, display.x, display.y);
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(display);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    ImGui::Begin("##workspace", nullptr, kHostFlags);
    ImGui::PopStyleVar(2);
    splitters();
    bodies_.clear();
    for (Region r : {Region::Left, Region::Right, Region::Bottom}) region(io, r);

    // The viewer last: it takes the camera input the panels left.
    const Rect& v = layout_.viewer;
    ImGui::SetCursorScreenPos(ImVec2(v.x, v.y));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(kViewerPadding, kViewerPadding));
    const bool shown = ImGui::BeginChild("Viewer", ImVec2(v.w, v.h), false, kViewerFlags);
    ImGui::PopStyleVar();
    if (shown)
        viewer_panel(io);
    else
        io.viewer.w = io.viewer.h = 0;
    ImGui::EndChild();
    ImGui::End();
    pending_.clear();  // a name no tab has is dropped
}

// The three splitters: left column | viewer, viewer | right column, viewer over bottom strip.
void Workspace::splitters() {
    const WorkspaceLayout& l = layout_;
    const Rect& v = l.viewer;
    float left = l.splits.left, right = l.splits.right, bottom = l.splits.bottom;
    float centre = v.w, above = v.h;
    const float height = l.regions[size_t(Region::Left)].h;
    // A dragged split is kept as asked; the others stay the window's defaults until dragged.
    bool moved = false;
    if (splitter("##split_left", ImRect(left, 0, left + kGap, height), ImGuiAxis_X, left, centre,
                 kMinLeft, l.viewer_min_width)) {
        moved = true;
        wanted_.left = left;
    }
    if (splitter("##split_right", ImRect(v.right(), 0, v.right() + kGap, height), ImGuiAxis_X,
                 centre, right, l.viewer_min_width, kMinRight)) {
        moved = true;
        wanted_.right = right;
    }
    if (splitter("##split_bottom", ImRect(v.x, v.bottom(), v.right(), v.bottom() + kGap),
                 ImGuiAxis_Y, above, bottom, kMinViewerHeight, kMinBottom)) {
        moved = true;
        wanted_.bottom = bottom;
    }
    if (!moved) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    layout_ = layout(wanted_, display.x, display.y);
    ImGui::MarkIniSettingsDirty();
}

// A region: its tab bar, and the open tab's panel in a child that scrolls on its own.
void Workspace::region(PanelIo& io, Region r) {
    const Rect& rect = layout_.regions[size_t(r)];
    ImGui::SetCursorScreenPos(ImVec2(rect.x, rect.y));
    const bool shown =
        ImGui::BeginChild(region_name(r), ImVec2(rect.w, rect.h), false, kRegionFlags);
    if (shown && ImGui::BeginTabBar("##tabs")) {
        for (const PanelEntry& p : panel_list()) {
            if (p.region != r) continue;
            const bool wanted =
                std::find(pending_.begin(), pending_.end(), p.name) != pending_.end();
            const bool open =
                ImGui::BeginTabItem(p.name, nullptr, wanted ? ImGuiTabItemFlags_SetSelected : 0);
            tabs_[p.name] = item_rect();
            if (!open) continue;
            std::string& open_tab = open_[size_t(r)];
            if (open_tab != p.name) {
                if (!open_tab.empty()) ImGui::MarkIniSettingsDirty();  // remembered
                open_tab = p.name;
            }
            if (ImGui::BeginChild(p.name, ImVec2(0, 0), false,
                                  ImGuiWindowFlags_HorizontalScrollbar)) {
                const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
                bodies_[p.name] = {at.x, at.y, size.x, size.y};
                p.draw(io);
            }
            ImGui::EndChild();
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::EndChild();
}

}  // namespace ds::ui
