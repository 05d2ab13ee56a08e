// Draws: count_draws' table, one row per scene draw group — mesh, material, node (its first
// instance's), instances, visible pixels, samples passed, wasted fragments, the Hi-Z verdict
// (hiz=on; an unsafe disagreement with samples passed in red) and the shaded fragments of each
// counting pass. Every column sorts (a click on its header), the filter
// keeps rows whose mesh, material or node contains the text, fully occluded draws are marked,
// and selecting a row keeps only its pixels bright in the viewer (ViewerState::draw). Off:
// one button turns count_draws on.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>
#include <string>

#include <imgui.h>

#include "renderer/passes/draw_counts.h"
#include "renderer/passes/hiz.h"
#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

int64_t total_wasted(const DrawReport& d) {
    int64_t sum = 0;
    for (const auto& [pass, n] : d.wasted_fragments) sum += n;
    return sum;
}

// A numeric column's value; none where it was not measured (sorted last).
std::optional<int64_t> number(const DrawReport& d, int column) {
    switch (column) {
        case kDrawGroup:
            return d.group;
        case kDrawInstances:
            return d.instances;
        case kDrawVisible:
            return d.visible_pixels ? std::optional<int64_t>(*d.visible_pixels) : std::nullopt;
        case kDrawSamples:
            return d.samples_passed ? std::optional<int64_t>(*d.samples_passed) : std::nullopt;
        case kDrawWasted:
            if (d.wasted_fragments.empty()) return std::nullopt;
            return total_wasted(d);
        case kDrawHiz:
            return d.hiz ? std::optional<int64_t>(int64_t(*d.hiz)) : std::nullopt;
        default:
            break;
    }
    const size_t k = size_t(column - kDrawShaded);
    if (column < kDrawShaded || k >= d.shaded_fragments.size()) return std::nullopt;
    return int64_t(d.shaded_fragments[k].second);
}

const std::string& text(const DrawReport& d, int column) {
    return column == kDrawMesh       ? d.name.mesh
           : column == kDrawMaterial ? d.name.material
                                     : d.name.node;
}

}  // namespace

std::vector<size_t> draw_rows(const std::vector<DrawReport>& draws, const std::string& filter,
                              int column, bool ascending) {
    const std::string needle = lower(filter);
    std::vector<size_t> rows;
    for (size_t i = 0; i < draws.size(); ++i) {
        const SurfaceName& n = draws[i].name;
        if (needle.empty() || lower(n.mesh).find(needle) != std::string::npos ||
            lower(n.material).find(needle) != std::string::npos ||
            lower(n.node).find(needle) != std::string::npos)
            rows.push_back(i);
    }
    const bool textual = column == kDrawMesh || column == kDrawMaterial || column == kDrawNode;
    std::stable_sort(rows.begin(), rows.end(), [&](size_t a, size_t b) {
        if (textual) {
            const int c = text(draws[a], column).compare(text(draws[b], column));
            return ascending ? c < 0 : c > 0;
        }
        const std::optional<int64_t> x = number(draws[a], column), y = number(draws[b], column);
        if (!x || !y) return x.has_value() && !y.has_value();  // nulls last either way
        return ascending ? *x < *y : *x > *y;
    });
    return rows;
}

namespace {

void cell(const std::optional<int64_t>& v) {
    ImGui::TableNextColumn();
    if (v)
        ImGui::Text("%lld", static_cast<long long>(*v));
    else
        ImGui::TextDisabled("-");
}

void hiz_cell(const DrawReport& d) {
    ImGui::TableNextColumn();
    if (!d.hiz) {
        ImGui::TextDisabled("-");
    } else if (d.hiz_unsafe) {
        ImGui::TextColored(ImVec4(1.0f, 0.25f, 0.25f, 1.0f), "%s UNSAFE", hiz_verdict_name(*d.hiz));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Hi-Z says it cannot be seen, yet its occlusion queries passed");
    } else {
        ImGui::TextUnformatted(hiz_verdict_name(*d.hiz));
    }
}

void row(PanelIo& io, const DrawReport& d, size_t passes) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const bool selected = io.viewer.draw == int(d.group);
    char label[32];
    std::snprintf(label, sizeof label, "%u%s", d.group, d.occluded ? " occluded" : "");
    if (d.occluded) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.2f, 1.0f));
    // Selecting a draw keeps its pixels bright in whatever the viewer shows; again: none.
    if (ImGui::Selectable(label, selected, ImGuiSelectableFlags_SpanAllColumns))
        io.viewer.draw = selected ? -1 : int(d.group);
    if (d.occluded) ImGui::PopStyleColor();
    for (int c : {kDrawMesh, kDrawMaterial, kDrawNode}) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(text(d, c).c_str());
    }
    for (int c = kDrawInstances; c < kDrawShaded + int(passes); ++c) {
        if (c == kDrawHiz)
            hiz_cell(d);
        else
            cell(number(d, c));
    }
}

// What a column's number means: its header's tooltip.
std::string column_help(int column, const DrawsResult& f, const std::string& pass) {
    switch (column) {
        case kDrawGroup:
            return "draw group: its index among the scene's draw groups (a mesh and a range of "
                   "its instances, what forward draws in one call). 'occluded': the visibility "
                   "pass drew it and none of it shows";
        case kDrawMesh:
            return "the group's mesh";
        case kDrawMaterial:
            return "the group's material";
        case kDrawNode:
            return "the scene node of the group's first instance";
        case kDrawInstances:
            return "instances in the group";
        case kDrawVisible:
            return "pixels where the prepass's nearest surface (surface_id) is one of the "
                   "group's triangles; the column sums to the frame's covered pixels (msaa > 1: "
                   "sample 0's). '-': no prepass, or a group it does not draw (blend, decals)";
        case kDrawSamples:
            return "samples that passed the depth test in " + f.samples_pass +
                   " (precise occlusion queries, summed over the group's draws; msaa > 1 "
                   "counts each sample). '-': that pass does not draw the group";
        case kDrawWasted:
            return "fragments: shaded minus visible pixels, summed over the passes drawn from "
                   "the camera that shaded the group (the columns on the right; the shadow "
                   "pass is not one): fragment shader runs that do not show";
        case kDrawHiz:
            return "hiz=on: the Hi-Z test's verdict on the group's instances, from their "
                   "bounds against the depth pyramid. visible: may be seen (or crosses the "
                   "near plane); occluded: every sample it could cover lies behind; outside: "
                   "off screen or beyond the far plane. UNSAFE: occluded, yet samples passed";
        default:
            return "fragments that ran " + pass +
                   "'s fragment shader for this group (counted on entry, exact; with early-Z "
                   "only those that passed the depth test)";
    }
}

// Columns as wide as their content, scrolled sideways when the strip is narrower.
void table(PanelIo& io, const DrawsResult& result) {
    const std::vector<DrawReport>& draws = result.draws;
    std::vector<std::string> passes;
    for (const auto& [pass, n] : draws.front().shaded_fragments) passes.push_back(pass);
    const int columns = kDrawShaded + int(passes.size());
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX |
                                  ImGuiTableFlags_ScrollY | ImGuiTableFlags_Sortable |
                                  ImGuiTableFlags_Resizable;
    if (!ImGui::BeginTable("draws", columns, flags, scrolling_table_size())) return;
    ImGui::TableSetupScrollFreeze(1, 1);  // the group's number and the header stay
    ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_DefaultSort, 0, kDrawGroup);
    ImGui::TableSetupColumn("mesh", 0, 0, kDrawMesh);
    ImGui::TableSetupColumn("material", 0, 0, kDrawMaterial);
    ImGui::TableSetupColumn("node", 0, 0, kDrawNode);
    ImGui::TableSetupColumn("inst", 0, 0, kDrawInstances);
    ImGui::TableSetupColumn("visible", 0, 0, kDrawVisible);
    ImGui::TableSetupColumn("samples", 0, 0, kDrawSamples);
    ImGui::TableSetupColumn("wasted", 0, 0, kDrawWasted);
    ImGui::TableSetupColumn("Hi-Z", 0, 0, kDrawHiz);
    for (size_t k = 0; k < passes.size(); ++k)
        ImGui::TableSetupColumn(passes[k].c_str(), 0, 0, ImGuiID(kDrawShaded + k));
    std::vector<std::string> help;
    for (int c = 0; c < columns; ++c)
        help.push_back(
            column_help(c, result, c >= kDrawShaded ? passes[size_t(c - kDrawShaded)] : ""));
    header_row_with_help(help);
    int column = kDrawGroup;
    bool ascending = true;
    if (const ImGuiTableSortSpecs* specs = ImGui::TableGetSortSpecs(); specs && specs->SpecsCount) {
        column = int(specs->Specs[0].ColumnUserID);
        ascending = specs->Specs[0].SortDirection != ImGuiSortDirection_Descending;
    }
    Inspector::PanelState& state = io.inspector.panel_state();
    state.draw_rows = draw_rows(draws, state.draw_filter.data(), column, ascending);
    for (size_t i : state.draw_rows) row(io, draws[i], passes.size());
    ImGui::EndTable();
}

void summary(const DrawsResult& f, const HizResult* hiz) {
    size_t occluded = 0;
    for (const DrawReport& d : f.draws) occluded += d.occluded;
    ImGui::Text("%s, %zu fully occluded; samples passed: %s",
                counted(f.draws.size(), "draw", "draws").c_str(), occluded, f.samples_pass.c_str());
    if (!f.visible_note.empty()) ImGui::TextDisabled("%s", f.visible_note.c_str());
    if (hiz && hiz->unsafe) {
        const uint64_t unsafe = *hiz->unsafe;
        if (unsafe)
            ImGui::TextColored(ImVec4(1.0f, 0.25f, 0.25f, 1.0f),
                               "Hi-Z: %llu unsafe (not visible, yet samples passed)",
                               static_cast<unsigned long long>(unsafe));
        else
            ImGui::TextDisabled("Hi-Z: no unsafe disagreement with samples passed");
    }
}

}  // namespace

void draws_panel(PanelIo& io) {
    const FrameResult& frame = io.inspector.frame();
    const DrawsResult* draws = frame.find<DrawsResult>();
    if (!draws || draws->draws.empty()) {
        if (!knob_value(io.inspector.settings(), passes::DrawCountsPass::kKnob)) {
            ImGui::TextDisabled("count_draws is off");
            ImGui::SameLine();
            if (ImGui::SmallButton("turn on"))
                io.actions.push_back(SetSetting{passes::DrawCountsPass::kKnob.name, "on"});
        } else {
            ImGui::TextDisabled("no draws counted yet");
        }
        return;
    }
    summary(*draws, frame.find<HizResult>());
    Inspector::PanelState& state = io.inspector.panel_state();
    ImGui::SetNextItemWidth(220);
    ImGui::InputTextWithHint("##filter", "filter mesh / material / node", state.draw_filter.data(),
                             state.draw_filter.size());
    if (io.viewer.draw >= 0) {
        ImGui::SameLine();
        if (ImGui::SmallButton("clear selection")) io.viewer.draw = -1;
    }
    table(io, *draws);
}

}  // namespace ds::ui
