// Settings: every knob of the registry (renderer/settings), grouped as the registry groups
// them, a widget by type, the registry's help text as tooltip. A change is an action: it
// applies on the next frame (the renderer rebuilds what the knob invalidates).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <imgui.h>
#include <glm/glm.hpp>

#include "renderer/settings/frame_knobs.h"
#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

void tooltip(const SettingDef& def) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::Text("%s (%s: %s, default %s)", def.name.c_str(), def.type_name().c_str(),
                def.range_text().c_str(), def.default_value.c_str());
    ImGui::TextUnformatted(def.help.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

// The values of a small integer range the registry accepts (msaa: 1, 2, 4, 8).
std::vector<int> accepted_ints(const SettingDef& def) {
    std::vector<int> out;
    Settings probe;
    for (int v = int(def.min); v <= int(def.max); ++v) {
        try {
            probe.set(def.name, std::to_string(v));
            out.push_back(v);
        } catch (const std::exception&) {
        }
    }
    return out;
}

// The number a keyword knob starts from when its keyword is unticked: the middle of the range
// (alpha_cutoff: 0.5, glTF's default), except fov, znear and zfar, whose keyword means the
// camera's own (the middle of the planes' range would put znear beyond zfar).
std::string number_for_keyword(PanelIo& io, const SettingDef& def) {
    double v = 0.5 * (def.min + def.max);
    const scene::Camera& camera = io.inspector.camera();
    if (def.name == knobs::kFov.name) v = double(glm::degrees(camera.yfov));
    if (def.name == knobs::kZnear.name) v = double(camera.znear);
    if (def.name == knobs::kZfar.name) v = double(camera.zfar);
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", std::clamp(v, def.min, def.max));
    return text;
}

// A change is an action: it applies on the next frame.
void set_knob(PanelIo& io, const SettingDef& def, std::string value) {
    io.actions.push_back(SetSetting{def.name, std::move(value)});
}

void bool_knob(PanelIo& io, const SettingDef& def, const std::string& value) {
    bool on = value == "on";
    if (ImGui::Checkbox(def.name.c_str(), &on)) set_knob(io, def, on ? "on" : "off");
}

void enum_knob(PanelIo& io, const SettingDef& def, const std::string& value) {
    if (ImGui::BeginCombo(def.name.c_str(), value.c_str())) {
        for (const std::string& c : def.choices)
            if (ImGui::Selectable(c.c_str(), c == value)) set_knob(io, def, c);
        ImGui::EndCombo();
    }
}

// A small range as a list of the values it accepts, a wide one as a slider.
void int_knob(PanelIo& io, const SettingDef& def, const std::string& value) {
    const char* label = def.name.c_str();
    int v = std::stoi(value);
    if (def.max - def.min <= 8) {
        if (ImGui::BeginCombo(label, value.c_str())) {
            for (int option : accepted_ints(def)) {
                // msaa: a sample count the device refuses is shown, disabled, with the reason.
                const std::vector<int>& counts = io.inspector.device().msaa_counts;
                const bool refused =
                    def.name == knobs::kMsaa.name &&
                    std::find(counts.begin(), counts.end(), option) == counts.end();
                const std::string text =
                    std::to_string(option) + (refused ? " (not on this device)" : "");
                if (refused) ImGui::BeginDisabled();
                if (ImGui::Selectable(text.c_str(), option == v))
                    set_knob(io, def, std::to_string(option));
                if (refused) ImGui::EndDisabled();
            }
            ImGui::EndCombo();
        }
    } else if (ImGui::SliderInt(label, &v, int(def.min), int(def.max))) {
        set_knob(io, def, std::to_string(v));
    }
}

// A keyword ("material") or a number: the keyword's box, then the slider it disables.
void float_knob(PanelIo& io, const SettingDef& def, const std::string& value) {
    const bool keyword =
        std::find(def.choices.begin(), def.choices.end(), value) != def.choices.end();
    if (!def.choices.empty()) {
        bool use_keyword = keyword;
        const std::string box = def.choices.front() + "##" + def.name;
        if (ImGui::Checkbox(box.c_str(), &use_keyword))
            set_knob(io, def, use_keyword ? def.choices.front() : number_for_keyword(io, def));
        tooltip(def);
        ImGui::SameLine();
    }
    // At the keyword the slider shows the value in use (the scene camera's planes and fov).
    float v = std::stof(keyword ? number_for_keyword(io, def) : value);
    if (keyword) ImGui::BeginDisabled();
    if (ImGui::SliderFloat(def.name.c_str(), &v, float(def.min), float(def.max), "%.3g")) {
        char text[32];
        std::snprintf(text, sizeof text, "%.4g", v);
        set_knob(io, def, text);
    }
    if (keyword) ImGui::EndDisabled();
}

// Free text (lists), applied on Enter.
void text_knob(PanelIo& io, const SettingDef& def, const std::string& value) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, "%s", value.c_str());
    if (ImGui::InputText(def.name.c_str(), buffer, sizeof buffer,
                         ImGuiInputTextFlags_EnterReturnsTrue))
        set_knob(io, def, buffer);
}

// One knob: its type's widget, yellow when it differs from the default, the help as tooltip.
void knob(PanelIo& io, const SettingDef& def) {
    const std::string& value = io.inspector.settings().get(def.name);
    const bool changed = value != def.default_value;
    if (changed) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.85f, 0.4f, 1.0f));
    switch (def.type) {
        case SettingType::Bool:
            bool_knob(io, def, value);
            break;
        case SettingType::Enum:
            enum_knob(io, def, value);
            break;
        case SettingType::Int:
            int_knob(io, def, value);
            break;
        case SettingType::Float:
            float_knob(io, def, value);
            break;
        default:  // Map: free text
            text_knob(io, def, value);
            break;
    }
    if (changed) ImGui::PopStyleColor();
    tooltip(def);
}

}  // namespace

void settings_panel(PanelIo& io) {
    const auto& defs = SettingsRegistry::instance().all();
    std::vector<std::string> groups;
    for (const SettingDef& d : defs)
        if (std::find(groups.begin(), groups.end(), d.group) == groups.end())
            groups.push_back(d.group);
    if (ImGui::SmallButton("reset all")) io.actions.push_back(ResetSettings{});
    ImGui::SameLine();
    ImGui::TextDisabled("changed knobs are yellow");
    // Widgets take what the knob names leave (about 150 units), at least 45 % of a narrow tab.
    const float avail = ImGui::GetContentRegionAvail().x;
    ImGui::PushItemWidth(std::max(0.45f * avail, avail - 150.0f));
    for (const std::string& group : groups) {
        // IDs by group and knob: a group and a knob may share a name ("msaa").
        ImGui::PushID(group.c_str());
        if (ImGui::CollapsingHeader(group.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
            for (const SettingDef& d : defs) {
                if (d.group != group) continue;
                ImGui::PushID(d.name.c_str());
                knob(io, d);
                ImGui::PopID();
            }
        }
        ImGui::PopID();
    }
    ImGui::PopItemWidth();
}

}  // namespace ds::ui
