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

// Window placement on first use (later runs take imgui.ini's).
struct PanelLayout {
    float width = 1600, height = 900;
    // Side columns: 340 and 460 at 1600 wide, narrower in a small window.
    float left() const { return std::min(340.0f, 0.22f * width); }
    float right() const { return std::min(460.0f, 0.29f * width); }
    // The panels that open over the lower viewer (Draws, Depth, Advisor, Overlays, Pixel,
    // Compare)
    // start collapsed, their title bars stacked from 55% of the height down, one per slot;
    // opened, each spans the viewer's width down to the bottom.
    enum Slot : int { kDraws, kDepth, kAdvisor, kOverlays, kPixel, kCompare, kTiler };
    float stacked_y(Slot slot) const { return height * 0.55f + 24.0f * float(slot); }
    void next_stacked_window(Slot slot) const;  // position, size and collapsed, first use
};

void passes_panel(PanelIo& io, const PanelLayout& layout);
void resources_panel(PanelIo& io, const PanelLayout& layout);
void viewer_panel(PanelIo& io, const PanelLayout& layout);
void settings_panel(PanelIo& io, const PanelLayout& layout);
void scene_panel(PanelIo& io, const PanelLayout& layout);
void shaders_panel(PanelIo& io, const PanelLayout& layout);
void depth_panel(PanelIo& io, const PanelLayout& layout);
void advisor_panel(PanelIo& io, const PanelLayout& layout);
void draws_panel(PanelIo& io, const PanelLayout& layout);
void overlays_panel(PanelIo& io, const PanelLayout& layout);
void pixel_panel(PanelIo& io, const PanelLayout& layout);
void compare_panel(PanelIo& io, const PanelLayout& layout);
void tiler_panel(PanelIo& io, const PanelLayout& layout);

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
// The sample view (viewer_samples.cpp): every visible pixel's samples over the image when
// zoomed in (the hovered texel outlined), a pixel's sample list (hover tooltip, Pixel panel).
void draw_samples(const PanelIo& io, ImVec2 scale, std::optional<std::array<uint32_t, 2>> hover);
void sample_table(const PixelSampleList& list);
void sample_tooltip(const PanelIo& io, uint32_t x, uint32_t y);
// The last capture's folder (or its error) and, with the compare view on, what it shows: the
// viewer's status line and the Compare panel's.
void capture_status(const Inspector& inspector);
void compare_status(const Inspector& inspector, const CompareState& state);

}  // namespace ds::ui
