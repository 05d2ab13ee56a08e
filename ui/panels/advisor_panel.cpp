// Advisor: does the prepass pay in this view? "measure" renders the current camera and
// settings with the prepass and without (a counting frame each for the exact fragment counts,
// then a few timed frames each; the UI waits meanwhile) and shows the overdraw, what each side
// costs, the predicted and the measured change of keeping the prepass, the verdict and seed
// 003's rule of thumb (overdraw > 2) against it. Until measured it says what it would do.
#include <imgui.h>

#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

constexpr const char* kWhat =
    "renders this view twice more: with the prepass and without it (everything else as set), "
    "one counting frame each (count_fragments=on: exact fragments) and 5 timed frames each "
    "(GPU medians, without counting). The UI waits meanwhile.";

// One row of the two-column table: with the prepass, without.
void row(const char* label, const char* format, double with, double without) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(label);
    ImGui::TableNextColumn();
    ImGui::Text(format, with);
    ImGui::TableNextColumn();
    ImGui::Text(format, without);
}

void sides_table(const capture::Advice& a) {
    const capture::AdviceSide& on = a.input.with_prepass;
    const capture::AdviceSide& off = a.input.without;
    // As wide as its content: no wrapping inside (a wrapped label in a column fitted to its
    // content printed one letter per line).
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    ImGui::PushTextWrapPos(-1.0f);
    if (!ImGui::BeginTable("sides", 3, flags, ImVec2(table_fit_width("sides"), 0))) {
        ImGui::PopTextWrapPos();
        return;
    }
    ImGui::TableSetupColumn("measured");
    ImGui::TableSetupColumn("with prepass");
    ImGui::TableSetupColumn("without");
    ImGui::TableHeadersRow();
    row("forward shaded", "%.0f", double(on.forward_shaded), double(off.forward_shaded));
    row("depth_prepass + resolve ms", "%.3f", on.depth_ms, off.depth_ms);
    row("forward ms", "%.3f", on.forward_ms, off.forward_ms);
    row("frame ms", "%.3f", on.frame_ms, off.frame_ms);
    row("forward ns / fragment", "%.2f", a.ns_per_fragment_with, a.ns_per_fragment_without);
    ImGui::EndTable();
    ImGui::PopTextWrapPos();
}

void advice_section(const Inspector& in) {
    const capture::Advice& a = *in.advice();
    ImGui::TextDisabled("measured: %s", in.advice_label().c_str());
    ImGui::Text("overdraw %.3f (%s covered)", a.overdraw,
                counted(a.input.without.covered_pixels, "pixel", "pixels").c_str());
    sides_table(a);
    ImGui::Text("keeping the prepass: predicted %+.3f ms, measured %+.3f ms", a.predicted_change_ms,
                a.measured_change_ms);
    ImGui::SameLine();
    help_marker(
        "measured: (depth_prepass + depth_resolve + forward) with the prepass minus the same "
        "without. predicted: the prepass's ms minus forward's ns per fragment without it times "
        "the fragments it saves. Negative: the prepass saves time. The whole frame's difference "
        "also holds the passes only the prepass feeds (gtao, ao_*, contact_shadows).");
    ImGui::Text("whole frame %+.3f ms", a.frame_change_ms);
    const ImVec4 colour = a.keep ? ImVec4(0.5f, 1, 0.5f, 1) : ImVec4(1, 0.7f, 0.3f, 1);
    ImGui::TextColored(colour, "verdict: %s", a.keep ? capture::kKeep : capture::kDrop);
    ImGui::Text("rule of thumb (overdraw > 2): %s, %s",
                a.rule_keep ? capture::kKeep : capture::kDrop, a.agrees() ? "agrees" : "disagrees");
    ImGui::SameLine();
    help_marker(
        "seed 003: avg_overdraw > 2.0 && shader cost is high. The shader-cost term is not "
        "measured by the rule here; forward's ns per fragment above is the measured cost.");
}

}  // namespace

void advisor_panel(PanelIo& io) {
    const Inspector& in = io.inspector;
    if (ImGui::Button("measure")) io.actions.push_back(MeasureAdvice{});
    ImGui::SameLine();
    help_marker(kWhat);
    if (!in.advice_error().empty())
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", in.advice_error().c_str());
    ImGui::PushTextWrapPos(0.0f);
    if (in.advice())
        advice_section(in);
    else
        ImGui::TextDisabled("not measured yet: \"measure\" %s", kWhat);
    ImGui::PopTextWrapPos();
}

}  // namespace ds::ui
