// Resources: every resource of the frame's graph with format, size, samples, semantic and
// lifetime; selecting an image shows it in the viewer.
#include <imgui.h>

#include "renderer/format/format.h"
#include "renderer/graph/names.h"
#include "ui/panels/panels.h"

namespace ds::ui {

void resources_panel(PanelIo& io) {
    const FrameResult& frame = io.inspector.frame();
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX |
                                  ImGuiTableFlags_ScrollY;
    if (ImGui::BeginTable("resources", 5, flags, scrolling_table_size())) {
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableSetupColumn("name");
        ImGui::TableSetupColumn("format");
        ImGui::TableSetupColumn("size");
        ImGui::TableSetupColumn("semantic");
        ImGui::TableSetupColumn("lifetime");
        ImGui::TableHeadersRow();
        for (const ResourceSummary& r : frame.resources) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            if (r.is_image) {
                if (ImGui::Selectable(r.name.c_str(), r.name == io.viewer.resource,
                                      ImGuiSelectableFlags_SpanAllColumns))
                    io.actions.push_back(SelectResource{r.name});
            } else {
                ImGui::TextDisabled("%s", r.name.c_str());
            }
            ImGui::TableNextColumn();
            if (r.is_image)
                ImGui::TextUnformatted(format::name(r.format).c_str());
            else
                ImGui::TextDisabled("buffer");
            ImGui::TableNextColumn();
            if (r.is_image && r.samples > 1)
                ImGui::Text("%ux%u x%u", r.width, r.height, r.samples);
            else if (r.is_image)
                ImGui::Text("%ux%u", r.width, r.height);
            else
                ImGui::Text("%llu B", static_cast<unsigned long long>(r.bytes));
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r.is_image ? graph::semantic_name(r.semantic) : "");
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(graph::lifetime_name(r.lifetime));
        }
        ImGui::EndTable();
    }
}

}  // namespace ds::ui
