// Depth: what the Z-fighting diagnostics found this frame. zfight's pairs of surfaces (mesh,
// material, node; pixels and the smallest gap in depth steps) and equal_check's holes and
// ties with the surfaces involved; a click shows the image behind them. When a diagnostic is
// off, one button turns it on; when the frame left it out, the report's reason. Precision:
// the size of one depth step against distance for this frame's format, planes and direction
// and for the alternatives, with the scene's depth range shaded.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "renderer/format/format.h"
#include "renderer/passes/equal_check.h"
#include "renderer/passes/zfight.h"
#include "renderer/view/precision.h"
#include "renderer/view/readout.h"
#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

std::string surface_text(const SurfaceName& s) {
    return s.node + " (" + s.mesh + ", " + s.material + ")";
}

// "on" button, or why the frame skipped it; true when the diagnostic has results to show.
bool diagnostic_state(PanelIo& io, const char* knob, bool has_results) {
    if (has_results) return true;
    const Inspector& in = io.inspector;
    if (in.settings().get(knob) != "on") {
        ImGui::TextDisabled("%s is off", knob);
        ImGui::SameLine();
        ImGui::PushID(knob);
        if (ImGui::SmallButton("turn on")) io.actions.push_back(SetSetting{knob, "on"});
        ImGui::PopID();
        return false;
    }
    for (const std::string& s : in.frame().skipped)
        if (s.rfind(std::string(knob) + ":", 0) == 0) ImGui::TextDisabled("%s", s.c_str());
    return false;
}

void zfight_section(PanelIo& io) {
    const FrameResult& frame = io.inspector.frame();
    const ZfightResult* zfight = frame.find<ZfightResult>();
    if (!diagnostic_state(io, "zfight", zfight != nullptr)) return;
    const ZfightResult& z = *zfight;
    ImGui::Text("%s, %s (gap <= %s)", counted(z.pixels, "pixel fights", "pixels fight").c_str(),
                counted(z.pairs.size(), "pair", "pairs").c_str(),
                counted(z.steps, "step", "steps").c_str());
    if (ImGui::SmallButton("view zfight")) io.actions.push_back(SelectResource{"zfight"});
    ImGui::SameLine();
    if (ImGui::SmallButton("view surface_id")) io.actions.push_back(SelectResource{"surface_id"});
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX |
                                  ImGuiTableFlags_ScrollY;
    if (z.pairs.empty() || !ImGui::BeginTable("pairs", 4, flags, ImVec2(0, 110))) return;
    ImGui::TableSetupColumn("a");
    ImGui::TableSetupColumn("b");
    ImGui::TableSetupColumn("pixels");
    ImGui::TableSetupColumn("min steps");
    ImGui::TableHeadersRow();
    for (size_t i = 0; i < z.pairs.size(); ++i) {
        const ZfightPair& p = z.pairs[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        // Selecting a pair shows only its pixels in the zfight view; again: all of them.
        const bool selected = io.viewer.zfight_pair == int(i);
        ImGui::PushID(int(i));
        if (ImGui::Selectable(surface_text(p.a).c_str(), selected,
                              ImGuiSelectableFlags_SpanAllColumns)) {
            io.viewer.zfight_pair = selected ? -1 : int(i);
            io.actions.push_back(SelectResource{"zfight"});
        }
        ImGui::PopID();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(surface_text(p.b).c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%llu", static_cast<unsigned long long>(p.pixels));
        ImGui::TableNextColumn();
        ImGui::Text("%u", p.min_steps);
    }
    ImGui::EndTable();
}

void equal_check_section(PanelIo& io) {
    const FrameResult& frame = io.inspector.frame();
    const EqualCheckResult* equal = frame.find<EqualCheckResult>();
    if (!diagnostic_state(io, "equal_check", equal != nullptr)) return;
    const EqualCheckResult& e = *equal;
    ImGui::Text("%s, %s shaded more than once", counted(e.holes, "hole", "holes").c_str(),
                counted(e.multiple, "pixel", "pixels").c_str());
    if (ImGui::SmallButton("view equal_check")) io.actions.push_back(SelectResource{"equal_check"});
    for (const EqualCheckSurface& s : e.surfaces)
        ImGui::BulletText("%s: %s, %s", surface_text(s.name).c_str(),
                          counted(s.holes, "hole", "holes").c_str(),
                          counted(s.multiple, "tie", "ties").c_str());
}

// The scene's bounds as view depths from the camera, within the planes.
std::pair<double, double> scene_depth_range(const Inspector& in, double n, double f) {
    const scene::Bounds& b = in.scene().bounds;
    const scene::Camera& cam = in.camera();
    double lo = f, hi = n;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                               (i & 4) ? b.max.z : b.min.z);
        const double z = glm::dot(corner - cam.position, cam.forward);
        lo = std::min(lo, z);
        hi = std::max(hi, z);
    }
    return {std::clamp(lo, n, f), std::clamp(hi, n, f)};
}

struct Curve {
    view::DepthConfig config;
    const char* label;
    ImU32 colour;
};

// log10 step against log10 distance, n .. f, for every configuration; the frame's is thick.
// The plot's area and its two log axes: distance (ln..lf) and step (lo..hi).
struct PlotFrame {
    ImVec2 p0, size;
    double ln = 0, lf = 1, lo = 0, hi = 1;
    ImVec2 to_screen(double lz, double ls) const {
        return ImVec2(p0.x + float((lz - ln) / (lf - ln)) * size.x,
                      p0.y + size.y - float((ls - lo) / std::max(hi - lo, 1e-9)) * size.y);
    }
};

// A line per decade of distance, labelled; the step's decades as faint lines.
void plot_grid(ImDrawList* dl, const PlotFrame& f) {
    const ImU32 grid = IM_COL32(255, 255, 255, 28), label = IM_COL32(200, 200, 200, 160);
    for (double e = std::ceil(f.ln); e <= f.lf; e += 1.0) {
        const float x = f.to_screen(e, f.lo).x;
        dl->AddLine(ImVec2(x, f.p0.y), ImVec2(x, f.p0.y + f.size.y), grid);
        dl->AddText(ImVec2(x + 2, f.p0.y + f.size.y - ImGui::GetTextLineHeight()), label,
                    view::length_text(float(std::pow(10.0, e))).c_str());
    }
    const double every = std::max(1.0, std::ceil((f.hi - f.lo) / 6.0));
    for (double e = std::ceil(f.lo / every) * every; e <= f.hi; e += every) {
        const float y = f.to_screen(f.ln, e).y;
        dl->AddLine(ImVec2(f.p0.x, y), ImVec2(f.p0.x + f.size.x, y), grid);
        if (y < f.p0.y + f.size.y - 2.0f * ImGui::GetTextLineHeight())  // clear of the x labels
            dl->AddText(ImVec2(f.p0.x + 2, y), label,
                        view::length_text(float(std::pow(10.0, e))).c_str());
    }
}

// Under the mouse: each curve's step at that distance.
void plot_tooltip(const PlotFrame& f, const std::array<Curve, 6>& curves) {
    if (!ImGui::IsItemHovered()) return;
    const double lz = f.ln + (ImGui::GetIO().MousePos.x - f.p0.x) / f.size.x * (f.lf - f.ln);
    const double z = std::pow(10.0, std::clamp(lz, f.ln, f.lf));
    std::string tip = "at " + view::length_text(float(z)) + ", one step is:";
    for (const Curve& curve : curves)
        tip += std::string("\n  ") + curve.label + ": " +
               view::length_text(float(view::step_at(curve.config, z)));
    ImGui::SetTooltip("%s", tip.c_str());
}

void precision_plot(const Inspector& in, const std::array<Curve, 6>& curves, int current) {
    const view::DepthConfig& c = curves[size_t(current)].config;
    PlotFrame f;
    f.ln = std::log10(c.znear);
    f.lf = std::log10(c.zfar);
    constexpr int kSamples = 96;
    auto sample_z = [&](int i) {
        return std::pow(10.0, f.ln + (f.lf - f.ln) * (i + 0.5) / kSamples);
    };
    f.lo = 1e300;
    f.hi = -1e300;
    for (const Curve& curve : curves)
        for (int i = 0; i < kSamples; ++i) {
            const double s = std::log10(std::max(view::step_at(curve.config, sample_z(i)), 1e-30));
            f.lo = std::min(f.lo, s);
            f.hi = std::max(f.hi, s);
        }
    f.p0 = ImGui::GetCursorScreenPos();
    f.size = ImVec2(std::max(ImGui::GetContentRegionAvail().x, 100.0f), 150.0f);
    ImGui::InvisibleButton("precision plot", f.size);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(f.p0, ImVec2(f.p0.x + f.size.x, f.p0.y + f.size.y),
                      IM_COL32(20, 20, 24, 255));
    plot_grid(dl, f);
    const auto [front, back] = scene_depth_range(in, c.znear, c.zfar);
    dl->AddRectFilled(ImVec2(f.to_screen(std::log10(front), 0).x, f.p0.y),
                      ImVec2(f.to_screen(std::log10(back), 0).x, f.p0.y + f.size.y),
                      IM_COL32(80, 80, 110, 90));
    for (size_t k = 0; k < curves.size(); ++k) {
        std::array<ImVec2, kSamples> points;
        for (int i = 0; i < kSamples; ++i) {
            const double z = sample_z(i);
            points[size_t(i)] = f.to_screen(
                std::log10(z), std::log10(std::max(view::step_at(curves[k].config, z), 1e-30)));
        }
        dl->AddPolyline(points.data(), kSamples, curves[k].colour, 0,
                        int(k) == current ? 3.0f : 1.2f);
    }
    plot_tooltip(f, curves);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped(
        "x: distance, znear to zfar; y: one depth step; both log. Shaded: the scene's depth "
        "range. Unorm steps are the same either way round: reverse-Z helps floats only.");
    ImGui::PopStyleColor();
}

void precision_section(PanelIo& io) {
    const FrameResult& frame = io.inspector.frame();
    if (!frame.depth) return;
    const DepthResult& d = *frame.depth;
    const double n = d.znear, f = d.zfar;
    const uint32_t bits = format::depth_bits(d.format);
    const std::array<Curve, 6> curves = {{
        {{32, true, n, f}, "reverse-Z d32f", IM_COL32(90, 220, 120, 255)},
        {{24, true, n, f}, "reverse-Z d24", IM_COL32(90, 170, 230, 255)},
        {{16, true, n, f}, "reverse-Z d16", IM_COL32(170, 120, 230, 255)},
        {{32, false, n, f}, "forward-Z d32f", IM_COL32(240, 200, 80, 255)},
        {{24, false, n, f}, "forward-Z d24", IM_COL32(240, 130, 60, 255)},
        {{16, false, n, f}, "forward-Z d16", IM_COL32(230, 70, 70, 255)},
    }};
    int current = 0;
    for (size_t k = 0; k < curves.size(); ++k)
        if (curves[k].config.bits == bits && curves[k].config.reverse_z == d.reverse_z)
            current = int(k);
    ImGui::Text("this frame: %s, znear %g, zfar %g", curves[size_t(current)].label, n, f);
    precision_plot(io.inspector, curves, current);
    for (size_t k = 0; k < curves.size(); ++k) {  // the legend
        if (k % 3) ImGui::SameLine();
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(curves[k].colour), "%s%s",
                           curves[k].label, int(k) == current ? " (this frame)" : "");
    }
}

}  // namespace

void depth_panel(PanelIo& io) {
    if (ImGui::CollapsingHeader("Z-fighting", ImGuiTreeNodeFlags_DefaultOpen)) zfight_section(io);
    if (ImGui::CollapsingHeader("EQUAL check", ImGuiTreeNodeFlags_DefaultOpen))
        equal_check_section(io);
    if (ImGui::CollapsingHeader("Precision", ImGuiTreeNodeFlags_DefaultOpen)) precision_section(io);
}

}  // namespace ds::ui
