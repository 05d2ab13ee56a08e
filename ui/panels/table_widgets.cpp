// Shared table widgets: a header row whose tooltips say what each column's numbers mean; the
// width that keeps a table's columns from being squeezed.
#include <algorithm>
#include <cmath>

#include <imgui.h>
#include <imgui_internal.h>  // ImGuiTable: the columns' ideal width at the last frame

#include "ui/panels/panels.h"

namespace ds::ui {

void header_row_with_help(const std::vector<std::string>& help) {
    ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
    for (int c = 0; c < ImGui::TableGetColumnCount(); ++c) {
        if (!ImGui::TableSetColumnIndex(c)) continue;
        ImGui::TableHeader(ImGui::TableGetColumnName(c));  // a click sorts (sortable tables)
        if (size_t(c) >= help.size() || help[size_t(c)].empty() || !ImGui::IsItemHovered())
            continue;
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
        ImGui::TextUnformatted(help[size_t(c)].c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

float table_fit_width(const char* str_id) {
    const ImGuiTable* table = ImGui::TableFindByID(ImGui::GetID(str_id));
    return table ? std::ceil(table->ColumnsAutoFitWidth) + 1.0f : 0.0f;
}

ImVec2 scrolling_table_size(int rows) {
    const float least = float(rows) * ImGui::GetTextLineHeightWithSpacing();
    return ImVec2(0.0f, std::max(ImGui::GetContentRegionAvail().y, least));
}

}  // namespace ds::ui
