// Diagnose: "what is wrong with this view?" in one click. The diagnosis
// (capture/diagnose/diagnose_run.h) runs every detector that applies on the current camera,
// settings and size, off the UI thread; its findings are rows ranked by severity then magnitude.
// Selecting one highlights its pixels over the image (while the view is the one diagnosed) and
// opens the panel with its details (Depth, Draws, Passes or Advisor); its surfaces and fix are
// listed below.
#include <imgui.h>

#include "capture/diagnose/finding_json.h"
#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

using diagnose::Diagnosis;
using diagnose::Finding;
using diagnose::Severity;

ImVec4 severity_colour(Severity s) {
    switch (s) {
        case Severity::Error:
            return ImVec4(1.0f, 0.42f, 0.42f, 1.0f);
        case Severity::Warning:
            return ImVec4(1.0f, 0.75f, 0.3f, 1.0f);
        case Severity::Info:
            return ImVec4(0.55f, 0.8f, 1.0f, 1.0f);
        case Severity::Hint:
            break;
    }
    return ImVec4(0.7f, 0.7f, 0.7f, 1.0f);
}

// "357,836 fragments", "1.14 x": as diagnose's own text writes it.
std::string magnitude_text(const diagnose::Magnitude& m) {
    if (m.value == double(int64_t(m.value))) return diagnose::grouped(m.value) + " " + m.unit;
    char text[64];
    std::snprintf(text, sizeof text, "%.3g %s", m.value, m.unit.c_str());
    return text;
}

void run_line(PanelIo& io) {
    const Inspector& in = io.inspector;
    ImGui::BeginDisabled(in.diagnosing());
    if (ImGui::Button("Diagnose this view")) io.actions.push_back(Diagnose{});
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (in.diagnosing())
        ImGui::TextDisabled("diagnosing... %.0f s (the view keeps its last frame)",
                            in.diagnosing_seconds());
    else
        help_marker(
            "Renders this view with every measurement that applies turned on (never a "
            "setting that changes the image), then the prepass advisor's frames, and "
            "ranks what it finds: errors (visible artefacts), warnings (wasted work), "
            "infos (advice). `depthscope diagnose` does the same from the command line.");
    if (!in.diagnosis_error().empty())
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", in.diagnosis_error().c_str());
}

void summary_line(const Inspector& in, const Diagnosis& d) {
    ImGui::Text("%s at %ux%u: %s, %s, %s; %s", d.scene.c_str(), d.width, d.height,
                counted(d.count(Severity::Error), "error", "errors").c_str(),
                counted(d.count(Severity::Warning), "warning", "warnings").c_str(),
                counted(d.count(Severity::Info), "info", "infos").c_str(),
                counted(d.frames, "frame", "frames").c_str());
    if (!in.diagnosis_current())
        ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f),
                           "of an earlier view (camera, settings or size changed): pixels "
                           "hidden; diagnose again");
}

void findings_table(PanelIo& io, const Diagnosis& d) {
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX |
                                  ImGuiTableFlags_ScrollY;
    const float height = std::min(
        ImGui::GetContentRegionAvail().y * 0.6f,
        ImGui::GetTextLineHeightWithSpacing() * float(std::max<size_t>(d.findings.size(), 3) + 1));
    if (!ImGui::BeginTable("findings", 4, flags, ImVec2(0, std::max(height, 80.0f)))) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("severity");
    ImGui::TableSetupColumn("code");
    ImGui::TableSetupColumn("magnitude");
    ImGui::TableSetupColumn("finding");
    header_row_with_help({"error: a visible artefact; warning: wasted work; info: advice",
                          "the finding's code, as in diagnose --json (glTF-Validator's shape)",
                          "how much: pixels, fragments, draws or a ratio, as the unit says",
                          "what was found, naming the surfaces (mesh / material / node)"});
    for (size_t i = 0; i < d.findings.size(); ++i) {
        const Finding& f = d.findings[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::PushID(int(i));
        const bool selected = io.viewer.finding == int(i);
        if (ImGui::Selectable("##row", selected, ImGuiSelectableFlags_SpanAllColumns))
            io.actions.push_back(SelectFinding{selected ? -1 : int(i)});
        ImGui::SameLine();
        ImGui::TextColored(severity_colour(f.severity), "%s", severity_name(f.severity));
        ImGui::PopID();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(f.code.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(magnitude_text(f.magnitude).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(f.message.c_str());
    }
    ImGui::EndTable();
}

void details(const Inspector& in, const Finding& f) {
    ImGui::Separator();
    ImGui::TextColored(severity_colour(f.severity), "%s %s", severity_name(f.severity),
                       f.code.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled(
        "(%s; %s)", f.detector.c_str(),
        f.pixels.empty() ? "covers no pixel of the image"
        : in.diagnosis_current()
            ? counted(f.pixels.size(), "pixel highlighted", "pixels highlighted").c_str()
            : "pixels hidden: another view");
    ImGui::TextWrapped("%s", f.message.c_str());
    if (!f.fix.empty()) ImGui::TextWrapped("fix: %s", f.fix.c_str());
    for (const diagnose::FindingSurface& s : f.surfaces)
        ImGui::BulletText("%s / %s / %s%s%s", s.mesh.c_str(), s.material.c_str(), s.node.c_str(),
                          s.pointer.empty() ? "" : "  ", s.pointer.c_str());
}

void skipped_list(const Diagnosis& d) {
    if (d.skipped.empty()) return;
    const std::string label = "not run: " + counted(d.skipped.size(), "detector", "detectors");
    if (!ImGui::TreeNode(label.c_str())) return;
    for (const diagnose::SkippedDetector& s : d.skipped)
        ImGui::BulletText("%s: %s", s.detector.c_str(), s.reason.c_str());
    ImGui::TreePop();
}

}  // namespace

bool diagnose_panel_wants_tab(PanelIo& io) {
    Inspector::PanelState& state = io.inspector.panel_state();
    if (io.inspector.diagnoses_started() == state.diagnoses_shown) return false;
    state.diagnoses_shown = io.inspector.diagnoses_started();  // a new diagnosis: show it
    return true;
}

void diagnose_panel(PanelIo& io) {
    const Inspector& in = io.inspector;
    run_line(io);
    if (!in.diagnosis()) {
        ImGui::TextDisabled("no diagnosis of this scene yet");
        return;
    }
    const Diagnosis& d = *in.diagnosis();
    summary_line(in, d);
    if (d.findings.empty())
        ImGui::TextUnformatted("nothing found");
    else
        findings_table(io, d);
    const int selected = io.viewer.finding;
    if (selected >= 0 && size_t(selected) < d.findings.size())
        details(in, d.findings[size_t(selected)]);
    skipped_list(d);
}

}  // namespace ds::ui
