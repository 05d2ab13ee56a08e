#include "ui/layer_viewer.h"

#include <algorithm>

#include <imgui.h>

namespace ds::ui {

namespace {

constexpr float kColumn = 460.0f;  // the left column's width, pixels
constexpr size_t kEqualKind = 4;   // capture::kLayerImageKinds: the EQUAL check's marks

std::string text(const nlohmann::json& j, const char* key) {
    if (!j.contains(key)) return "";
    return j.at(key).is_string() ? j.at(key).get<std::string>() : j.at(key).dump();
}

}  // namespace

LayerViewer::LayerViewer(capture::LayerCaptureData data) : data_(std::move(data)) {
    select(0, 0);
}

void LayerViewer::select(size_t image, size_t kind) {
    image_ = image;
    kind_ = kind;
    rgba_.clear();
    ++version_;
    if (image_ >= data_.images.size()) return;
    const capture::LayerPassImages& p = data_.images[image_];
    if (p.counts[kind_].empty()) kind_ = 0;  // this pass has no such image
    rgba_ = kind_ == kEqualKind ? capture::marks_rgba(p.counts[kind_])
                                : capture::count_heat_rgba(p.counts[kind_], p.max[kind_]);
}

void LayerViewer::draw(TargetSize target) {
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize({kColumn, float(target.height)});
    ImGui::Begin("Layer capture", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    draw_summary();
    draw_passes();
    draw_depth_checks();
    draw_draws();
    ImGui::End();
    update_blit(target);
    update_readout(target);
}

void LayerViewer::draw_summary() {
    const nlohmann::json& r = data_.report;
    ImGui::TextWrapped("%s, frame %s (%s)", text(r, "application").c_str(),
                       text(r, "frame").c_str(), text(r, "delimiter").c_str());
    ImGui::TextWrapped("%s", r.contains("device") ? text(r.at("device"), "name").c_str() : "");
    if (r.contains("cost"))
        ImGui::Text("capture: %.0f ms, counters %.1f MiB", r.at("cost").value("capture_ms", 0.0),
                    r.at("cost").value("counter_bytes", 0.0) / (1024.0 * 1024.0));
    const auto& not_analysed = r.value("not_analysed", nlohmann::json::array());
    if (!not_analysed.empty() &&
        ImGui::CollapsingHeader(
            ("not analysed (" + std::to_string(not_analysed.size()) + ")").c_str()))
        for (const auto& why : not_analysed)
            ImGui::BulletText("%s", why.get<std::string>().c_str());
}

void LayerViewer::draw_passes() {
    ImGui::Separator();
    ImGui::TextUnformatted("Passes");
    for (size_t i = 0; i < data_.images.size(); ++i) {
        const capture::LayerPassImages& p = data_.images[i];
        const std::string label = p.name + "  " + std::to_string(p.width) + "x" +
                                  std::to_string(p.height) + "##pass" + std::to_string(i);
        if (ImGui::Selectable(label.c_str(), i == image_)) select(i, kind_);
    }
    if (image_ >= data_.images.size()) return;
    const capture::LayerPassImages& p = data_.images[image_];
    for (size_t k = 0; k < capture::kLayerImageKinds.size(); ++k) {
        if (p.counts[k].empty()) continue;
        if (k) ImGui::SameLine();
        if (ImGui::RadioButton(capture::kLayerImageKinds[k], k == kind_)) select(image_, k);
    }
    if (kind_ == kEqualKind)
        ImGui::TextUnformatted("magenta: hole, yellow: tie");
    else
        ImGui::Text("heat map: black 0 .. white %u", p.max[kind_]);
}

// The Z-fight pairs and the EQUAL check's totals (settings zfight, equal_check).
void LayerViewer::draw_depth_checks() {
    const nlohmann::json& r = data_.report;
    if (r.contains("zfight") &&
        ImGui::CollapsingHeader(
            ("Z-fight pairs (" + std::to_string(r["zfight"]["pairs"].size()) + ")").c_str())) {
        ImGui::Text("within %s steps; %s pixels", text(r["zfight"], "steps").c_str(),
                    text(r["zfight"], "pixels").c_str());
        for (const auto& pair : r["zfight"]["pairs"]) {
            const auto who = [](const nlohmann::json& x) {
                return text(x, "name") + (x.contains("instance") ? " #" + text(x, "instance") : "");
            };
            ImGui::Bullet();
            ImGui::TextWrapped("%s / %s: %s px, %s steps (%s)", who(pair["a"]).c_str(),
                               who(pair["b"]).c_str(), text(pair, "pixels").c_str(),
                               text(pair, "min_steps").c_str(), text(pair, "pass").c_str());
        }
    }
    if (r.contains("equal_check"))
        ImGui::Text("EQUAL check: %s holes, %s ties", text(r["equal_check"], "holes").c_str(),
                    text(r["equal_check"], "multiple").c_str());
}

void LayerViewer::draw_draws() {
    if (image_ >= data_.images.size()) return;
    const uint32_t pass = data_.images[image_].pass;
    ImGui::Separator();
    ImGui::TextUnformatted("Draws");
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_Resizable;
    if (!ImGui::BeginTable("draws", 5, flags, {0, ImGui::GetContentRegionAvail().y})) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    for (const char* h : {"draw", "shaded", "discarded", "rasterized", "passed"})
        ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    for (const auto& d : data_.report.at("draws")) {
        if (d.value("pass", 0u) != pass) continue;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(text(d, "name").c_str());
        if (d.contains("not_analysed")) {
            ImGui::TableNextColumn();
            ImGui::TextDisabled("not analysed: %s", text(d, "not_analysed").c_str());
            continue;
        }
        for (const char* key : {"shaded", "discarded", "rasterized", "samples_passed"}) {
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(text(d, key).c_str());
        }
    }
    ImGui::EndTable();
}

void LayerViewer::update_blit(TargetSize target) {
    blit_ = ViewerBlit{};
    if (image_ >= data_.images.size() || rgba_.empty()) return;
    const capture::LayerPassImages& p = data_.images[image_];
    const float area_w = std::max(1.0f, float(target.width) - kColumn);
    const float area_h = std::max(1.0f, float(target.height));
    const float scale = std::min(area_w / float(p.width), area_h / float(p.height));
    blit_.rgba8 = &rgba_;
    blit_.width = p.width;
    blit_.height = p.height;
    blit_.dst_w = float(p.width) * scale;
    blit_.dst_h = float(p.height) * scale;
    blit_.dst_x = kColumn + (area_w - blit_.dst_w) / 2;
    blit_.dst_y = (area_h - blit_.dst_h) / 2;
    blit_.src_w = float(p.width);
    blit_.src_h = float(p.height);
    blit_.nearest = scale >= 1.0f;
    blit_.version = version_;
}

void LayerViewer::update_readout(TargetSize target) {
    readout_.clear();
    if (!blit_.rgba8 || ImGui::GetIO().WantCaptureMouse) return;
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const auto texel = texel_at(blit_, target, mouse.x, mouse.y);
    if (!texel) return;
    const capture::LayerPassImages& p = data_.images[image_];
    const size_t i = size_t((*texel)[1]) * p.width + (*texel)[0];
    readout_ = std::to_string((*texel)[0]) + ", " + std::to_string((*texel)[1]) + ": shaded " +
               std::to_string(p.counts[0][i]) + ", discarded " + std::to_string(p.counts[1][i]) +
               ", rasterized " + std::to_string(p.counts[2][i]);
    if (!p.counts[3].empty()) readout_ += ", competing " + std::to_string(p.counts[3][i]);
    if (!p.counts[kEqualKind].empty() && p.counts[kEqualKind][i])
        readout_ += p.counts[kEqualKind][i] == 1 ? ", EQUAL hole" : ", EQUAL tie";
    ImGui::SetNextWindowPos({mouse.x + 16, mouse.y + 16});
    ImGui::BeginTooltip();
    ImGui::TextUnformatted(readout_.c_str());
    ImGui::EndTooltip();
}

}  // namespace ds::ui
