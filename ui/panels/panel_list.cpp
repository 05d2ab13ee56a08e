// Which panel goes where: the workspace's tabs, region by region, in tab order. Adding a panel
// is its file (ui/panels/NAME_panel.cpp, declared in panels.h) and one line here.
#include "ui/panels/panels.h"

namespace ds::ui {

const std::vector<PanelEntry>& panel_list() {
    static const std::vector<PanelEntry> panels = {
        {"Settings", Region::Left, settings_panel},
        {"Scene", Region::Left, scene_panel},
        {"Camera", Region::Left, camera_panel},
        {"Shaders", Region::Left, shaders_panel},
        {"Passes", Region::Right, passes_panel},
        {"Resources", Region::Right, resources_panel},
        {"Depth", Region::Right, depth_panel},
        {"Advisor", Region::Right, advisor_panel},
        {"Diagnose", Region::Bottom, diagnose_panel, diagnose_panel_wants_tab},
        {"Draws", Region::Bottom, draws_panel},
        {"Pixel", Region::Bottom, pixel_panel, pixel_panel_wants_tab},
        {"Overlays", Region::Bottom, overlays_panel},
        {"Compare", Region::Bottom, compare_panel},
        {"Tiler", Region::Bottom, tiler_panel},
        {"Tuning", Region::Bottom, tuning_panel},
    };
    return panels;
}

}  // namespace ds::ui
