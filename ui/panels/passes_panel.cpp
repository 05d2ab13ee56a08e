// Passes: the frame's passes in execution order with their GPU cost (this frame and the
// median of the last 120), shader invocations, exact counts (count_fragments=on) and a bar
// each, clear, measurement and read-back passes folded into one row; the selected pass's reads and
// writes (click one to view it) and its pipelines with their early-Z verdicts (also a tooltip on
// the row; lost ones in a warning colour); the frame-time history.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

void declarations(PanelIo& io, const PassResult& pass) {
    auto list = [&](const char* label, const std::vector<std::string>& names) {
        ImGui::TextDisabled("%s", label);
        ImGui::PushID(label);  // a resource may be both read and written
        for (const std::string& name : names) {
            ImGui::SameLine();
            if (ImGui::SmallButton(name.c_str())) io.actions.push_back(SelectResource{name});
        }
        ImGui::PopID();
        if (names.empty()) {
            ImGui::SameLine();
            ImGui::TextDisabled("-");
        }
    };
    list("reads ", pass.reads);
    list("writes", pass.writes);
}

const ImVec4 kLostColour(1.0f, 0.6f, 0.3f, 1.0f);  // a pipeline that loses early-Z

bool lost(const PipelineReport& r) {
    return r.early_z != "guaranteed";
}

// One line per pipeline the pass drew with: name, draws, early-Z verdict (or that it has no
// fragment stage, which is early-Z by construction).
void pipelines(const PassResult& pass) {
    for (const PipelineReport& r : pass.pipelines) {
        ImGui::Text("%s, %s:", r.name.c_str(), counted(r.draws, "draw", "draws").c_str());
        ImGui::SameLine();
        if (!r.fragment_stage)
            ImGui::TextDisabled("no fragment stage (depth only)");
        else if (lost(r))
            ImGui::TextColored(kLostColour, "early-Z %s", r.early_z.c_str());
        else
            ImGui::TextDisabled("early-Z %s", r.early_z.c_str());
    }
}

// count_fragments=on: one counting pass's rasterized, shaded and discarded fragments and quad
// lanes per shaded fragment ("-" where the device cannot count quads).
void count_row(const PassResult& p) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(p.name.c_str());
    for (const std::optional<uint64_t>& n :
         {p.rasterized_fragments, p.shaded_fragments, p.discarded_fragments}) {
        ImGui::TableNextColumn();
        if (n) ImGui::Text("%llu", static_cast<unsigned long long>(*n));
    }
    ImGui::TableNextColumn();
    if (p.quads && p.shaded_fragments && *p.shaded_fragments)
        ImGui::Text("%.2f", 4.0 * double(*p.quads) / double(*p.shaded_fragments));
    else if (p.shaded_fragments)
        ImGui::TextDisabled("-");
}

void pass_row(PanelIo& io, const PassResult& p, double worst) {
    const Inspector& in = io.inspector;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const bool selected = p.name == in.selected_pass();
    std::string label = p.name;
    if (!p.subpass_group.empty()) label = std::to_string(p.subpass) + ": " + p.name;  // subpass
    if (p.role != graph::PassRole::Frame)
        label += std::string(" (") + graph::pass_role_name(p.role) + ")";
    // A pass that drew with a pipeline that loses early-Z says so in its row (one bound with
    // nothing to draw, such as the MASK pipeline of a scene without MASK, does not count).
    const bool any_lost =
        std::any_of(p.pipelines.begin(), p.pipelines.end(),
                    [](const PipelineReport& r) { return lost(r) && r.draws > 0; });
    if (any_lost) ImGui::PushStyleColor(ImGuiCol_Text, kLostColour);
    if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_SpanAllColumns))
        io.actions.push_back(SelectPass{selected ? std::string() : p.name});
    if (any_lost) ImGui::PopStyleColor();
    if (!p.pipelines.empty() && ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        pipelines(p);
        ImGui::EndTooltip();
    }
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", p.gpu_ms);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", in.history().median(p.name));
    ImGui::TableNextColumn();
    ImGui::Text("%llu", static_cast<unsigned long long>(p.vertex_shader_invocations));
    ImGui::TableNextColumn();
    ImGui::Text("%llu", static_cast<unsigned long long>(p.fragment_shader_invocations));
    ImGui::TableNextColumn();
    const float fraction = worst > 0 ? float(p.gpu_ms / worst) : 0.0f;
    ImGui::ProgressBar(fraction, ImVec2(-1, ImGui::GetTextLineHeight()), "");
}

struct Column {
    const char* name;
    std::string meaning;
};

// The column headers, each with what its number means on this device as a tooltip.
void header_row(const std::vector<Column>& columns) {
    for (const Column& c : columns) ImGui::TableSetupColumn(c.name);
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 40.0f);  // the bar
    ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
    for (size_t i = 0; i < columns.size(); ++i) {
        ImGui::TableSetColumnIndex(int(i));
        ImGui::TableHeader(columns[i].name);
        if (ImGui::IsItemHovered()) {
            ImGui::BeginTooltip();
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
            ImGui::TextUnformatted(columns[i].meaning.c_str());
            ImGui::PopTextWrapPos();
            ImGui::EndTooltip();
        }
    }
}

std::vector<Column> pass_columns(const DeviceInfo& device) {
    return {{"pass", "graph pass, in execution order; orange: a pipeline without early-Z"},
            {"ms", "GPU time this frame, from timestamps around the pass"},
            {"median", "GPU time, median of the last 120 frames"},
            {"VS inv", "vertex-shader invocations (the device's pipeline statistic)"},
            {"FS inv", "fragment-shader invocations (the device's pipeline statistic): " +
                           device.fragment_statistic}};
}

const std::vector<Column>& count_columns() {
    static const std::vector<Column> columns = {
        {"counted pass", "the passes that count (count_fragments=on)"},
        {"rasterized",
         "exact: fragments the pass's draws rasterized, whatever the depth test made of them: "
         "depth complexity (a measurement draw with the depth test off)"},
        {"shaded",
         "exact: fragments that ran the fragment shader, counted on entry: with early-Z those "
         "that passed the depth test, without it every rasterized one"},
        {"discarded", "exact: of the shaded, those the alpha test discarded"},
        {"quad",
         "quad overdraw: lanes of the 2x2 quads that ran (helpers included) per shaded "
         "fragment, 1.00 at best; '-': the device has no quad subgroup operations in fragment "
         "shaders"}};
    return columns;
}

// The folded group of clear and read-back passes; true when it is open (then TreePop()).
bool support_row(int count, double ms) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    char label[64];
    std::snprintf(label, sizeof label, "clear, measure, read-back (%d)###support", count);
    const bool open = ImGui::TreeNodeEx(label, ImGuiTreeNodeFlags_SpanFullWidth);
    ImGui::TableNextColumn();
    ImGui::TextDisabled("%.2f", ms);
    return open;
}

// A render pass of subpasses (render_path=subpass): one row with the group's total, its passes
// nested under it; true when it is open (then TreePop()).
bool group_row(const std::string& group, size_t subpasses, double ms) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const std::string label = group + " [" + std::to_string(subpasses) + "]###group_" + group;
    const bool open = ImGui::TreeNodeEx(
        label.c_str(), ImGuiTreeNodeFlags_SpanFullWidth | ImGuiTreeNodeFlags_DefaultOpen);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "render pass of %zu subpasses (render_path=subpass): its passes nested, "
            "each after its subpass index; the Tiler panel has its attachments",
            subpasses);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", ms);
    return open;
}

// The frame's own passes in order, each run of one subpass group nested under its row.
void frame_rows(PanelIo& io, const FrameResult& frame, double worst) {
    const std::vector<PassResult>& passes = frame.passes;
    for (size_t i = 0; i < passes.size();) {
        const PassResult& p = passes[i];
        if (p.role != graph::PassRole::Frame) {
            ++i;
            continue;
        }
        if (p.subpass_group.empty()) {
            pass_row(io, p, worst);
            ++i;
            continue;
        }
        size_t end = i;
        double ms = 0.0;
        while (end < passes.size() && passes[end].subpass_group == p.subpass_group)
            ms += passes[end++].gpu_ms;
        if (group_row(p.subpass_group, passes[end - 1].subpass + 1, ms)) {
            for (size_t k = i; k < end; ++k) pass_row(io, passes[k], worst);
            ImGui::TreePop();
        }
        i = end;
    }
}

// The table of passes: the frame's own passes, then clears, measurements and read-backs folded
// into one row (they are timed and barriered like any pass, but are not the frame a user tunes).
void pass_table(PanelIo& io, const FrameResult& frame) {
    double worst = 0.0;
    for (const PassResult& p : frame.passes) worst = std::max(worst, p.gpu_ms);

    // count_fragments=on: the exact counts in a table of their own below.
    const bool counted = std::any_of(frame.passes.begin(), frame.passes.end(),
                                     [](const PassResult& p) { return p.shaded_fragments; });
    // As wide as their content; the tab scrolls sideways when the column is narrower.
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("passes", 6, flags, ImVec2(table_fit_width("passes"), 0))) return;
    header_row(pass_columns(io.inspector.device()));
    double support_ms = 0.0;
    int support = 0;
    frame_rows(io, frame, worst);
    for (const PassResult& p : frame.passes) {
        if (p.role != graph::PassRole::Frame) {
            support_ms += p.gpu_ms;
            ++support;
        }
    }
    if (support > 0 && support_row(support, support_ms)) {
        for (const PassResult& p : frame.passes)
            if (p.role != graph::PassRole::Frame) pass_row(io, p, worst);
        ImGui::TreePop();
    }
    ImGui::EndTable();
    if (!counted || !ImGui::BeginTable("counts", 6, flags, ImVec2(table_fit_width("counts"), 0)))
        return;
    header_row(count_columns());
    for (const PassResult& p : frame.passes)
        if (p.shaded_fragments) count_row(p);
    ImGui::EndTable();
}

// The selected pass: its name, reads and writes, shaded fragments where counted, pipelines.
void selected_pass(PanelIo& io, const FrameResult& frame) {
    for (const PassResult& p : frame.passes) {
        if (p.name != io.inspector.selected_pass()) continue;
        ImGui::Separator();
        ImGui::Text("%s", p.name.c_str());
        declarations(io, p);
        if (p.shaded_fragments)
            ImGui::Text("fragments: %llu rasterized, %llu shaded, %llu discarded",
                        static_cast<unsigned long long>(p.rasterized_fragments.value_or(0)),
                        static_cast<unsigned long long>(*p.shaded_fragments),
                        static_cast<unsigned long long>(p.discarded_fragments.value_or(0)));
        pipelines(p);
    }
}

void frame_time_plot(const PassHistory& history) {
    ImGui::Separator();
    std::vector<float> plot(history.frame_ms.begin(), history.frame_ms.end());
    float top = 0.0f;
    for (float v : plot) top = std::max(top, v);
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "frame GPU ms, last %zu (max %.1f)", plot.size(), top);
    ImGui::PlotLines("##frame", plot.data(), int(plot.size()), 0, overlay, 0.0f,
                     top * 1.2f + 0.001f, ImVec2(ImGui::GetContentRegionAvail().x, 70));
}

}  // namespace

void passes_panel(PanelIo& io) {
    const FrameResult& frame = io.inspector.frame();
    ImGui::Text("frame %.2f ms GPU, %.2f ms CPU record, %ux%u", frame.gpu_ms, frame.cpu_ms,
                frame.width, frame.height);
    pass_table(io, frame);
    // Why passes did not run, whole: wrapped at the column's edge.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    for (const std::string& s : frame.skipped) ImGui::TextWrapped("%s", s.c_str());
    ImGui::PopStyleColor();
    selected_pass(io, frame);
    frame_time_plot(io.inspector.history());
}

}  // namespace ds::ui
