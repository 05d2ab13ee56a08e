#include "ui/panels/plot_widget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

namespace ds::ui {
namespace {

struct Range {
    double lo = 0, hi = 1;
    double at(double v) const { return hi > lo ? (v - lo) / (hi - lo) : 0.5; }
};

void ranges(const capture::Plot& plot, Range& x, Range& y) {
    bool any = false;
    for (const capture::PlotSeries& s : plot.series)
        for (const auto& [px, py] : s.points) {
            x.lo = any ? std::min(x.lo, px) : px, x.hi = any ? std::max(x.hi, px) : px;
            y.lo = any ? std::min(y.lo, py) : py, y.hi = any ? std::max(y.hi, py) : py;
            any = true;
        }
    const double pad_x = (x.hi - x.lo) * 0.05, pad_y = (y.hi - y.lo) * 0.1;
    x.lo -= pad_x, x.hi += pad_x, y.lo -= pad_y, y.hi += pad_y;
}

ImU32 colour(uint32_t rgb) {
    return IM_COL32((rgb >> 16) & 0xff, (rgb >> 8) & 0xff, rgb & 0xff, 255);
}

}  // namespace

void plot_widget(const char* id, const capture::Plot& plot, float height) {
    ImGui::TextUnformatted(plot.title.c_str());
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size(std::max(ImGui::GetContentRegionAvail().x, 200.0f), height);
    ImGui::InvisibleButton(id, size);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y),
                      IM_COL32(20, 22, 26, 255));
    Range xr, yr;
    ranges(plot, xr, yr);
    const float left = origin.x + 8, right = origin.x + size.x - 8;
    const float top = origin.y + 8, bottom = origin.y + size.y - 8;
    const auto to_screen = [&](double x, double y) {
        return ImVec2(left + float(xr.at(x)) * (right - left),
                      bottom - float(yr.at(y)) * (bottom - top));
    };
    dl->AddRect(ImVec2(left, top), ImVec2(right, bottom), IM_COL32(90, 90, 90, 255));
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    std::string hover;
    for (const capture::PlotSeries& s : plot.series) {
        for (size_t i = 0; i < s.points.size(); ++i) {
            const ImVec2 p = to_screen(s.points[i].first, s.points[i].second);
            if (s.line && i > 0)
                dl->AddLine(to_screen(s.points[i - 1].first, s.points[i - 1].second), p,
                            colour(s.rgb), 2.0f);
            if (s.markers) dl->AddCircleFilled(p, 3.5f, colour(s.rgb));
            if (i < s.point_labels.size())
                dl->AddText(ImVec2(p.x + 5, p.y - 15), IM_COL32(200, 200, 200, 255),
                            s.point_labels[i].c_str());
            if (ImGui::IsItemHovered() && std::hypot(mouse.x - p.x, mouse.y - p.y) < 6.0f) {
                char text[160];
                std::snprintf(text, sizeof text, "%s%s%s\n%s %.4g\n%s %.4g", s.label.c_str(),
                              i < s.point_labels.size() ? ": " : "",
                              i < s.point_labels.size() ? s.point_labels[i].c_str() : "",
                              plot.x_label.c_str(), s.points[i].first, plot.y_label.c_str(),
                              s.points[i].second);
                hover = text;
            }
        }
    }
    if (!hover.empty()) ImGui::SetTooltip("%s", hover.c_str());
    ImGui::TextDisabled("x: %s, %.4g..%.4g   y: %s, %.4g..%.4g", plot.x_label.c_str(), xr.lo, xr.hi,
                        plot.y_label.c_str(), yr.lo, yr.hi);
    for (const capture::PlotSeries& s : plot.series) {
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(colour(s.rgb)), "-- %s", s.label.c_str());
        ImGui::SameLine();
    }
    ImGui::NewLine();
}

}  // namespace ds::ui
