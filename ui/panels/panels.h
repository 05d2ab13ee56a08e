#pragma once
// The inspector's panels, one file each. A panel reads the inspector's state and returns what
// the user asked for as actions (Inspector::apply carries them out); view-only state (the
// viewer's zoom and decode range, the camera input) it writes directly. No Vulkan calls.
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "renderer/passes/draw_counts.h"
#include "ui/inspector.h"

namespace ds::ui {

// "1 pair", "3 pairs": a count with its noun, singular or plural.
inline std::string counted(uint64_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

struct PanelIo {
    const Inspector& inspector;
    ViewerState& viewer;
    CameraInput& camera;
    std::vector<Action>& actions;
};

// The panels' content, each drawn inside its tab of the workspace (workspace.h): no window of
// their own. The viewer is the workspace's centre.
void passes_panel(PanelIo& io);
void resources_panel(PanelIo& io);
void viewer_panel(PanelIo& io);
void settings_panel(PanelIo& io);
void scene_panel(PanelIo& io);
void camera_panel(PanelIo& io);
void shaders_panel(PanelIo& io);
void depth_panel(PanelIo& io);
void advisor_panel(PanelIo& io);
void draws_panel(PanelIo& io);
void overlays_panel(PanelIo& io);
void pixel_panel(PanelIo& io);
void compare_panel(PanelIo& io);
void tiler_panel(PanelIo& io);
void diagnose_panel(PanelIo& io);
void tuning_panel(PanelIo& io);
// A new pick wants the Pixel panel shown (once per pick), a new diagnosis the Diagnose panel.
bool pixel_panel_wants_tab(PanelIo& io);
bool diagnose_panel_wants_tab(PanelIo& io);

// One tab of the workspace: its name, the region it lives in, what draws its content and,
// where it has one, when it asks to be shown (true: its tab is selected at the next frame).
// Selecting a tab from code: Inspector::workspace().select(name).
struct PanelEntry {
    const char* name;
    Region region;
    void (*draw)(PanelIo& io);
    bool (*wants_tab)(PanelIo& io) = nullptr;
};
// Every panel, in tab order within each region (panel_list.cpp: a panel is one line there).
const std::vector<PanelEntry>& panel_list();

// The Draws panel's table: column ids (kDrawShaded + k: shaded fragments of the k-th counting
// pass of the draws' shaded_fragments), and the rows to show — indices into `draws` whose
// mesh, material or node contains `filter` (case-insensitive), sorted by `column`; ties and
// unmeasured (null) values keep the scene's order, nulls last.
enum DrawColumn : int {
    kDrawGroup,
    kDrawMesh,
    kDrawMaterial,
    kDrawNode,
    kDrawInstances,
    kDrawVisible,
    kDrawSamples,
    kDrawWasted,  // over the in-view passes
    kDrawHiz,     // hiz=on: the Hi-Z verdict (sorts visible, occluded, outside)
    kDrawShaded
};
std::vector<size_t> draw_rows(const std::vector<DrawReport>& draws, const std::string& filter,
                              int column, bool ascending);

// Shared widgets.
void help_marker(const char* text);  // "(?)" with a tooltip
// A table's header row (after its TableSetupColumn calls), each header's tooltip what the
// column's numbers mean: help[column] ("" or missing: none).
void header_row_with_help(const std::vector<std::string>& help);
// BeginTable's outer width for a fixed-fit table without ScrollX: the width its columns wanted
// at the last frame, so that none is squeezed (a narrower tab scrolls sideways instead); 0,
// the width available, before its first frame.
float table_fit_width(const char* str_id);
// A ScrollY table's outer size: the rest of the tab, at least `rows` rows high (a short tab
// scrolls to it: the table is never squeezed away).
ImVec2 scrolling_table_size(int rows = 8);
// The sample view (viewer_samples.cpp): every visible pixel's samples over the image when
// zoomed in (the hovered texel outlined), a pixel's sample list (hover tooltip, Pixel panel).
void draw_samples(const PanelIo& io, ImVec2 scale, std::optional<std::array<uint32_t, 2>> hover);
void sample_table(const PixelSampleList& list);
void sample_tooltip(const PanelIo& io, uint32_t x, uint32_t y);
// This scene's camera bookmarks: a name field and "add", each bookmark with "go" and
// "delete" (the Camera panel and the viewer's "bookmarks" popup).
void bookmark_list(PanelIo& io);
// The last capture's folder (or its error) and, with the compare view on, what it shows: the
// viewer's status line and the Compare panel's.
void capture_status(const Inspector& inspector);
void compare_status(const Inspector& inspector, const CompareState& state);

}  // namespace ds::ui
