// The viewer's MSAA sample view (issue 15): zoomed in to kSampleViewZoom screen pixels per
// texel or more, every visible pixel shows its samples at their positions (the standard
// table's, or approximate where the device's are not standard), each a square in the colour of
// the surface that holds it (the surface_id view's colours; the sky's for none); hovering a
// pixel lists its samples. The data is the frame's own (its MsaaSamples).
#include <algorithm>
#include <cmath>
#include <string>

#include <imgui.h>

#include "renderer/view/decode.h"
#include "ui/panels/panels.h"
#include "ui/viewer_blit.h"

namespace ds::ui {
namespace {

ImU32 rgb(std::array<uint8_t, 3> c, int alpha = 255) {
    return IM_COL32(c[0], c[1], c[2], alpha);
}

// An HDR colour shown as a colour: Reinhard per channel (the Pixel panel's swatches too).
ImVec4 hdr_shown(const std::array<float, 4>& c) {
    auto map = [](float v) { return std::isfinite(v) ? v / (1.0f + std::max(v, 0.0f)) : 1.0f; };
    return ImVec4(map(c[0]), map(c[1]), map(c[2]), 1.0f);
}

// A sample's colour in the view: its surface's, or without surface ids its own colour.
ImU32 sample_color(const MsaaSamples& s, const PixelSample& p) {
    if (!s.surface_ids) return ImGui::ColorConvertFloat4ToU32(hdr_shown(p.color));
    return p.surface ? rgb(view::surface_color(p.surface)) : rgb(view::kSkyColor);
}

std::string surface_text(const std::optional<SurfaceInfo>& info, uint32_t id) {
    if (id == 0) return "none (sky)";
    if (!info) return "surface " + std::to_string(id);
    return info->name.mesh + " / " + info->name.material + " (" + info->name.node + ") #" +
           std::to_string(info->triangle);
}

// One pixel's samples at their positions; the square's side scales with the zoom.
void pixel_samples(ImDrawList* draw, const MsaaSamples& s, uint32_t x, uint32_t y, ImVec2 at,
                   float side, ImVec2 to_screen) {
    const std::span<const PixelSample> pixel = s.pixel(x, y);
    const float half = std::clamp(side * 0.1f, 2.0f, 7.0f);
    bool standard = true;
    for (uint32_t i = 0; i < pixel.size(); ++i) {
        const view::SamplePosition p = sample_position(s.samples, i, standard);
        const ImVec2 c((at.x + p.x * side) / to_screen.x, (at.y + p.y * side) / to_screen.y);
        const float h = half / to_screen.x;
        draw->AddRectFilled(ImVec2(c.x - h - 1, c.y - h - 1), ImVec2(c.x + h + 1, c.y + h + 1),
                            IM_COL32(0, 0, 0, 230));
        draw->AddRectFilled(ImVec2(c.x - h, c.y - h), ImVec2(c.x + h, c.y + h),
                            sample_color(s, pixel[i]));
    }
}

}  // namespace

void draw_samples(const PanelIo& io, ImVec2 scale, std::optional<std::array<uint32_t, 2>> hover) {
    const MsaaSamples* s = io.inspector.shown_samples();
    if (!s) return;
    const ImGuiIO& imgui = ImGui::GetIO();
    const TargetSize target{uint32_t(imgui.DisplaySize.x * scale.x),
                            uint32_t(imgui.DisplaySize.y * scale.y)};
    BlitRegion r{};
    if (!clip_blit(io.inspector.viewer_blit(), target, r)) return;
    const float side = float(r.dx1 - r.dx0) / float(r.sx1 - r.sx0);  // framebuffer px per texel
    if (side < kSampleViewZoom - 1e-3f) return;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(ImVec2(float(r.dx0) / scale.x, float(r.dy0) / scale.y),
                       ImVec2(float(r.dx1) / scale.x, float(r.dy1) / scale.y), true);
    const uint32_t x0 = std::max<uint32_t>(r.sx0, s->rect.x);
    const uint32_t y0 = std::max<uint32_t>(r.sy0, s->rect.y);
    const uint32_t x1 = std::min<uint32_t>(r.sx1, s->rect.x + s->rect.width);
    const uint32_t y1 = std::min<uint32_t>(r.sy1, s->rect.y + s->rect.height);
    auto corner = [&](uint32_t x, uint32_t y) {
        return ImVec2(float(r.dx0) + float(x - r.sx0) * side,
                      float(r.dy0) + float(y - r.sy0) * side);
    };
    // Pixel edges: a thin grid, so each sample's pixel is plain.
    for (uint32_t x = x0; x <= x1 && y1 > y0; ++x) {
        const ImVec2 a = corner(x, y0), b = corner(x, y1);
        draw->AddLine(ImVec2(a.x / scale.x, a.y / scale.y), ImVec2(b.x / scale.x, b.y / scale.y),
                      IM_COL32(0, 0, 0, 90));
    }
    for (uint32_t y = y0; y <= y1 && x1 > x0; ++y) {
        const ImVec2 a = corner(x0, y), b = corner(x1, y);
        draw->AddLine(ImVec2(a.x / scale.x, a.y / scale.y), ImVec2(b.x / scale.x, b.y / scale.y),
                      IM_COL32(0, 0, 0, 90));
    }
    for (uint32_t y = y0; y < y1; ++y)
        for (uint32_t x = x0; x < x1; ++x) pixel_samples(draw, *s, x, y, corner(x, y), side, scale);
    if (hover && s->contains((*hover)[0], (*hover)[1])) {
        const ImVec2 a = corner((*hover)[0], (*hover)[1]);
        draw->AddRect(ImVec2(a.x / scale.x, a.y / scale.y),
                      ImVec2((a.x + side) / scale.x, (a.y + side) / scale.y),
                      IM_COL32(255, 220, 60, 255), 0.0f, 0, 2.0f);
    }
    draw->PopClipRect();
}

void sample_table(const PixelSampleList& list) {
    ImGui::Text("pixel (%u, %u): %s, %s", list.x, list.y,
                counted(list.samples, "sample", "samples").c_str(),
                counted(list.surfaces.size(), "surface", "surfaces").c_str());
    if (!list.standard_positions)
        ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1),
                           "positions not standard on this device: drawn approximate");
    if (!list.surface_ids)
        ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1),
                           "surfaces unknown: surface_id needs the prepass (prepass=off)");
    constexpr ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (ImGui::BeginTable("samples", 6, flags, ImVec2(table_fit_width("samples"), 0))) {
        for (const char* c : {"#", "position", "surface", "depth", "linear", "colour"})
            ImGui::TableSetupColumn(c);
        ImGui::TableHeadersRow();
        for (const SampleRow& row : list.rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%u", row.index);
            ImGui::TableNextColumn();
            ImGui::Text("%.4g, %.4g", row.position.x, row.position.y);
            ImGui::TableNextColumn();
            if (list.surface_ids)
                ImGui::TextUnformatted(surface_text(row.info, row.surface).c_str());
            else
                ImGui::TextDisabled("?");
            ImGui::TableNextColumn();
            ImGui::Text("%.9f", row.depth);
            ImGui::TableNextColumn();
            ImGui::Text("%.4f", row.linear_depth);
            ImGui::TableNextColumn();
            ImGui::ColorButton(("##s" + std::to_string(row.index)).c_str(), hdr_shown(row.color),
                               ImGuiColorEditFlags_NoTooltip, ImVec2(20, 12));
            ImGui::SameLine();
            ImGui::Text("%.3f %.3f %.3f", row.color[0], row.color[1], row.color[2]);
        }
        ImGui::EndTable();
    }
    if (!list.surface_ids) return;
    for (const SurfaceSamples& c : list.surfaces)
        ImGui::Text("%s  %s", mask_text(c.mask, list.samples).c_str(),
                    surface_text(c.info, c.surface).c_str());
}

void sample_tooltip(const PanelIo& io, uint32_t x, uint32_t y) {
    const std::optional<PixelSampleList> list = io.inspector.sample_list_at(x, y);
    if (!list) return;
    ImGui::BeginTooltip();
    sample_table(*list);
    ImGui::EndTooltip();
}

}  // namespace ds::ui
