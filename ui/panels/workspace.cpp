// The workspace's geometry and what it keeps in imgui.ini (workspace.h); drawing is in
// workspace_draw.cpp.
#include "ui/panels/workspace.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <imgui.h>
#include <imgui_internal.h>  // ImGuiSettingsHandler: our own imgui.ini entry

namespace ds::ui {
namespace {

constexpr const char* kIniType = "Workspace";
constexpr const char* kIniEntry = "layout";

// The columns' widths: what was wanted (0: a share of the window), at least their minimums,
// together no more than `budget` (what the viewer leaves). A window too small for both
// minimums shrinks them in proportion.
std::pair<float, float> column_widths(const Splits& wanted, float width, float budget) {
    float min_left = Workspace::kMinLeft, min_right = Workspace::kMinRight;
    if (min_left + min_right > budget) {
        const float k = budget / (min_left + min_right);
        min_left *= k;
        min_right *= k;
    }
    float left = wanted.left > 0 ? wanted.left : std::round(0.17f * width);
    float right = wanted.right > 0 ? wanted.right : std::round(0.26f * width);
    left = std::max(left, min_left);
    right = std::max(right, min_right);
    if (left + right > budget) {  // the right column gives way first, down to its minimum
        right = std::max(min_right, budget - left);
        left = budget - right;
    }
    return {std::floor(left), std::floor(right)};
}

// The bottom strip's height: wanted (0: a share of the window) within its minimum and what
// leaves the viewer its least height.
float bottom_height(const Splits& wanted, float height) {
    const float avail = height - Workspace::kGap;
    float low = Workspace::kMinBottom, high = avail - Workspace::kMinViewerHeight;
    if (high < low) low = high = std::floor(0.3f * avail);  // a very small window
    const float bottom = wanted.bottom > 0 ? wanted.bottom : std::round(0.28f * height);
    return std::floor(std::clamp(bottom, low, high));
}

void* ini_open(ImGuiContext*, ImGuiSettingsHandler* handler, const char* name) {
    return std::strcmp(name, kIniEntry) == 0 ? handler->UserData : nullptr;
}

void ini_line(ImGuiContext*, ImGuiSettingsHandler*, void* entry, const char* line) {
    static_cast<Workspace*>(entry)->read_ini_line(line);
}

void ini_write(ImGuiContext*, ImGuiSettingsHandler* handler, ImGuiTextBuffer* out) {
    const std::string lines = static_cast<const Workspace*>(handler->UserData)->ini_lines();
    out->appendf("[%s][%s]\n%s\n", kIniType, kIniEntry, lines.c_str());
}

}  // namespace

const char* region_name(Region region) {
    switch (region) {
        case Region::Left:
            return "left";
        case Region::Right:
            return "right";
        case Region::Bottom:
            return "bottom";
    }
    return "?";
}

WorkspaceLayout Workspace::layout(const Splits& wanted, float width, float height) {
    WorkspaceLayout out;
    const float w = std::max(width, 1.0f), h = std::max(height, 1.0f);
    out.viewer_min_width = std::ceil(kViewerShare * w) + 2.0f * kViewerPadding;
    const float budget = std::max(w - 2.0f * kGap - out.viewer_min_width, 0.0f);
    const auto [left, right] = column_widths(wanted, w, budget);
    const float bottom = bottom_height(wanted, h);
    out.splits = {left, right, bottom};
    const float centre_x = left + kGap, centre_w = std::max(w - left - right - 2.0f * kGap, 0.0f);
    out.viewer = {centre_x, 0.0f, centre_w, std::max(h - bottom - kGap, 0.0f)};
    out.regions[size_t(Region::Left)] = {0.0f, 0.0f, left, h};
    out.regions[size_t(Region::Right)] = {w - right, 0.0f, right, h};
    out.regions[size_t(Region::Bottom)] = {centre_x, h - bottom, centre_w, bottom};
    return out;
}

Workspace::Workspace() : context_(ImGui::GetCurrentContext()) {
    if (!context_) return;
    ImGuiSettingsHandler handler;
    handler.TypeName = kIniType;
    handler.TypeHash = ImHashStr(kIniType);
    handler.ReadOpenFn = ini_open;
    handler.ReadLineFn = ini_line;
    handler.WriteAllFn = ini_write;
    handler.UserData = this;
    context_->SettingsHandlers.push_back(handler);
}

Workspace::~Workspace() {
    if (!context_) return;
    ImVector<ImGuiSettingsHandler>& handlers = context_->SettingsHandlers;
    for (int i = 0; i < handlers.Size; ++i)
        if (handlers[i].UserData == this) {
            handlers.erase(handlers.begin() + i);
            break;
        }
}

void Workspace::select(const std::string& panel) {
    pending_.push_back(panel);
}

std::string Workspace::ini_lines() const {
    std::string out;
    char line[96];
    const std::pair<const char*, float> sizes[] = {
        {"left", wanted_.left}, {"right", wanted_.right}, {"bottom", wanted_.bottom}};
    for (const auto& [name, value] : sizes) {
        if (value <= 0) continue;  // never dragged: the window's default
        std::snprintf(line, sizeof line, "%s=%.0f\n", name, value);
        out += line;
    }
    for (size_t r = 0; r < kRegions; ++r)
        if (!open_[r].empty())
            out += std::string("tab_") + region_name(Region(r)) + "=" + open_[r] + "\n";
    return out;
}

void Workspace::read_ini_line(const std::string& line) {
    const size_t eq = line.find('=');
    if (eq == std::string::npos) return;
    const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    if (key.rfind("tab_", 0) == 0) {
        if (!value.empty()) select(value);  // a name no panel has is never matched: ignored
        return;
    }
    char* end = nullptr;
    const float v = std::strtof(value.c_str(), &end);
    if (end == value.c_str() || !std::isfinite(v) || v <= 0) return;  // clamped when laid out
    if (key == "left") wanted_.left = v;
    if (key == "right") wanted_.right = v;
    if (key == "bottom") wanted_.bottom = v;
}

}  // namespace ds::ui
