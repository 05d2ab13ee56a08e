// Compare: captures from the inspector (the Capture button; F12 anywhere) and the live frame
// against a pinned capture's final.png — split (live left of the divider, capture right) or
// diff (the pixels over 8/255 as a heat map, with their %). The capture written last is
// pinned; any capture folder can be pinned by path. The live frame is compared only at the
// capture's size: "render at the capture's size" makes it so.
#include <array>
#include <cstdio>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

const ImVec4 kError(1, 0.4f, 0.4f, 1);
const ImVec4 kWarning(1, 0.6f, 0.3f, 1);

// The pinned capture, and pinning another: the last written one, or a folder by path.
void pin_controls(PanelIo& io) {
    const Inspector& in = io.inspector;
    const auto& pinned = in.compare().pinned();
    if (pinned) {
        ImGui::Text("pinned: %s (%ux%u)", pinned->dir.c_str(), pinned->final_image.width,
                    pinned->final_image.height);
        ImGui::SameLine();
        if (ImGui::SmallButton("unpin")) io.actions.push_back(PinCapture{});
    } else {
        ImGui::TextDisabled("no capture pinned: a capture pins itself");
    }
}

// Any capture folder by path, or the last capture again.
void pin_other(PanelIo& io) {
    const Inspector& in = io.inspector;
    const auto& pinned = in.compare().pinned();
    std::array<char, 512>& path = in.panel_state().pin_path;
    ImGui::SetNextItemWidth(260);
    ImGui::InputTextWithHint("##pin", "capture folder", path.data(), path.size());
    ImGui::SameLine();
    if (ImGui::Button("pin") && path[0] != '\0')
        io.actions.push_back(PinCapture{std::filesystem::path(path.data())});
    if (!in.capture_path().empty() && (!pinned || pinned->dir != in.capture_path())) {
        ImGui::SameLine();
        if (ImGui::Button("pin the last capture"))
            io.actions.push_back(PinCapture{in.capture_path()});
    }
}

void mode_controls(PanelIo& io) {
    CompareState& c = io.viewer.compare;
    int mode = int(c.mode);
    ImGui::TextUnformatted("view:");
    ImGui::SameLine();
    ImGui::RadioButton("off", &mode, int(CompareMode::Off));
    ImGui::SameLine();
    ImGui::RadioButton("split", &mode, int(CompareMode::Split));
    ImGui::SameLine();
    ImGui::RadioButton("diff", &mode, int(CompareMode::Diff));
    c.mode = CompareMode(mode);
    if (c.mode == CompareMode::Split) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(160);
        ImGui::SliderFloat("divider", &c.divider, 0.0f, 1.0f, "%.2f");
    }
    const auto& pinned = io.inspector.compare().pinned();
    if (pinned) {
        ImGui::SameLine();
        char label[96];
        std::snprintf(label, sizeof label, "render at the capture's size (%ux%u)",
                      pinned->final_image.width, pinned->final_image.height);
        ImGui::Checkbox(label, &c.match_size);
    }
}

}  // namespace

void capture_status(const Inspector& in) {
    if (in.capturing())
        ImGui::TextColored(kWarning, "capturing... (the inspector waits for it)");
    else if (!in.capture_error().empty())
        ImGui::TextColored(kError, "capture: %s", in.capture_error().c_str());
    else if (!in.capture_path().empty())
        ImGui::Text("captured %s", in.capture_path().c_str());
    else
        ImGui::TextDisabled("F12: capture this frame");
}

void compare_status(const Inspector& in, const CompareState& state) {
    const CaptureCompare& c = in.compare();
    if (!c.active(state)) return;
    if (!c.status().empty()) {
        ImGui::TextColored(kWarning, "compare: %s", c.status().c_str());
        return;
    }
    const char* what = state.mode == CompareMode::Split ? "split: live | capture" : "diff";
    ImGui::Text("compare (%s): %.3f %% of pixels differ by >= %d/255 (%llu)", what, c.percent(),
                CaptureCompare::kThreshold,
                static_cast<unsigned long long>(c.differing().value_or(0)));
}

void compare_panel(PanelIo& io) {
    if (ImGui::Button("Capture")) io.actions.push_back(CaptureFrame{});
    ImGui::SameLine();
    help_marker(
        "Writes a capture of this frame (camera, settings, render size; final.png, every "
        "resource, report.json) into a new folder of captures/, through the live renderer, "
        "and pins it. F12 does the same anywhere in the window. `depthscope replay` renders "
        "it again bit for bit; `depthscope view --capture DIR` opens it.");
    ImGui::SameLine();
    capture_status(io.inspector);
    pin_controls(io);
    mode_controls(io);
    compare_status(io.inspector, io.viewer.compare);
    ImGui::Separator();
    pin_other(io);
}

}  // namespace ds::ui
