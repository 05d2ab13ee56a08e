#pragma once
// The inspector's workspace: one fixed layout over the whole window. The viewer is in the
// centre, a column of tabbed panels on each side and a strip of them under the viewer; the
// splits between them drag (imgui_internal's SplitterBehavior), never so far that the image
// gets less than kViewerShare of the window's width. Panels are content drawn inside a tab
// (panel_list() in panel_list.cpp: name, region, draw function); none is a window of its own,
// none moves, none lies over the image (tooltips, popups and menus aside). The split sizes
// and each region's open tab are kept in imgui.ini ("[Workspace][layout]", a settings handler
// of ours) and clamped to the window they are restored into.
#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

struct ImGuiContext;

namespace ds::ui {

struct PanelIo;

// Where a panel lives: a side column or the strip under the viewer.
enum class Region : int { Left, Right, Bottom };
constexpr size_t kRegions = 3;
const char* region_name(Region region);  // "left", "right", "bottom"

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
    float right() const { return x + w; }
    float bottom() const { return y + h; }
    bool intersects(const Rect& o) const {  // share more than an edge
        return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom();
    }
    bool contains(float px, float py) const {
        return px >= x && px < right() && py >= y && py < bottom();
    }
};

// The splits: the side columns' widths and the bottom strip's height, in ImGui units.
struct Splits {
    float left = 0, right = 0, bottom = 0;  // 0: the window's default
};

// Everything's place in a window of one size.
struct WorkspaceLayout {
    Rect viewer;                         // the centre: the Viewer's region (the image inside)
    std::array<Rect, kRegions> regions;  // by Region
    Splits splits;                       // the sizes in use: wanted, clamped
    float viewer_min_width = 0;          // the narrowest the viewer's region may get
};

class Workspace {
  public:
    static constexpr float kViewerShare = 0.55f;   // the image's least share of the width
    static constexpr float kGap = 6.0f;            // a splitter between two regions
    static constexpr float kViewerPadding = 6.0f;  // round the viewer's controls and image
    static constexpr float kMinLeft = 180.0f, kMinRight = 220.0f;
    static constexpr float kMinBottom = 64.0f, kMinViewerHeight = 200.0f;

    // Registers the "Workspace" settings handler with the current ImGui context, if any (read
    // at the context's first frame); the destructor removes it again.
    Workspace();
    ~Workspace();
    Workspace(const Workspace&) = delete;
    Workspace& operator=(const Workspace&) = delete;

    // The layout of a window of `width` x `height` for the `wanted` splits (0: defaults):
    // each region keeps its minimum and the viewer at least kViewerShare of the width for its
    // image; a too-small window shrinks the columns first.
    static WorkspaceLayout layout(const Splits& wanted, float width, float height);

    // One UI frame (inside ImGui::NewFrame): the regions with their tab bars, the open tab's
    // panel in each, the splitters, and the viewer last (it takes the camera input left).
    void draw(PanelIo& io);

    // Shows `panel`'s tab (a panel_list() name) in its region from the next frame on.
    void select(const std::string& panel);
    // The tab open in `region` at the last frame ("" before the first).
    const std::string& open_tab(Region region) const { return open_[size_t(region)]; }
    const Splits& splits() const { return wanted_; }
    void set_splits(const Splits& splits) { wanted_ = splits; }

    // What the last frame drew (tests): the layout, every tab header's rectangle and each
    // open panel's content area (where its first widget is).
    const WorkspaceLayout& last_layout() const { return layout_; }
    const std::map<std::string, Rect>& tab_rects() const { return tabs_; }
    const std::map<std::string, Rect>& panel_rects() const { return bodies_; }

    // The "[Workspace][layout]" ini entry: its lines and reading one back.
    std::string ini_lines() const;
    void read_ini_line(const std::string& line);

  private:
    void splitters();
    void region(PanelIo& io, Region r);

    Splits wanted_;
    WorkspaceLayout layout_;
    std::array<std::string, kRegions> open_;
    std::vector<std::string> pending_;  // tabs to select at the next frame
    std::map<std::string, Rect> tabs_, bodies_;
    ImGuiContext* context_ = nullptr;  // where the handler is registered
};

}  // namespace ds::ui
