// Viewer: the central viewport. Shows the final image or any graph resource decoded by its
// semantic (renderer/view), with the decode controls above and the hover readout below. The
// mouse drives the camera, or with Ctrl (or the "image" mouse mode) zooms and pans the image.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "renderer/graph/names.h"
#include "renderer/view/decode.h"
#include "renderer/view/heat.h"
#include "renderer/view/readout.h"
#include "ui/panels/panels.h"
#include "ui/viewer_blit.h"

namespace ds::ui {
namespace {

using view::count_legend;
using view::DecodedView;
using view::DepthView;
using view::is_perspective_depth;
using view::LegendStop;

// The resource picker (images and derived views such as forward_wasted), with the shown
// image's size and semantic after it.
void resource_picker(PanelIo& io, const InspectedImage* image) {
    ViewerState& v = io.viewer;
    ImGui::SetNextItemWidth(190);
    if (ImGui::BeginCombo("##resource", v.resource.c_str())) {
        for (const std::string& name : io.inspector.viewable())
            if (ImGui::Selectable(name.c_str(), name == v.resource))
                io.actions.push_back(SelectResource{name});
        ImGui::EndCombo();
    }
    if (image) {
        ImGui::SameLine();
        ImGui::TextDisabled("%ux%u %s", image->width, image->height,
                            graph::semantic_name(image->semantic));
    }
}

// What only some images have: a sample index (MSAA) and the depth mode (perspective depth).
void image_options(ViewerState& v, const InspectedImage* image) {
    if (image && image->samples > 1) {
        ImGui::SameLine();
        int sample = int(v.sample);
        ImGui::SetNextItemWidth(80);
        if (ImGui::SliderInt("sample", &sample, 0, int(image->samples) - 1))
            v.sample = uint32_t(sample);
    }
    if (image && is_perspective_depth(image->semantic)) {  // linear or raw
        ImGui::SameLine();
        int mode = int(v.params.depth);
        ImGui::RadioButton("linear", &mode, int(DepthView::Linear));
        ImGui::SameLine();
        ImGui::RadioButton("raw", &mode, int(DepthView::Raw));
        v.params.depth = DepthView(mode);
    }
}

// The value range mapped to black and white: auto-fit or manual, in the view's unit.
void range_controls(ViewerState& v, const DecodedView& view) {
    ImGui::Checkbox("auto-fit", &v.params.auto_fit);
    ImGui::SameLine();
    if (v.params.auto_fit) {  // show what auto-fit chose; editing switches to manual
        v.params.black = view.black;
        v.params.white = view.white;
    }
    ImGui::SetNextItemWidth(240);
    float range[2] = {v.params.black, v.params.white};
    const float speed = std::max(std::abs(range[1] - range[0]) * 0.005f, 1e-4f);
    if (ImGui::DragFloat2("black / white", range, speed, 0, 0, "%.4g")) {
        v.params.auto_fit = false;
        v.params.black = range[0];
        v.params.white = range[1];
    }
    if (!view.unit.empty()) {
        ImGui::SameLine();
        ImGui::TextDisabled("%s", view.unit.c_str());
    }
}

// The channel shown (all or one), and the exposure of an HDR colour.
void channel_controls(ViewerState& v, const InspectedImage* image) {
    ImGui::SameLine();
    ImGui::TextUnformatted(" channel");
    static const char* kChannels[] = {"all", "R", "G", "B", "A"};
    for (int c = -1; c < 4; ++c) {
        ImGui::SameLine();
        if (ImGui::RadioButton(kChannels[c + 1], v.params.channel == c)) v.params.channel = c;
    }
    if (image && image->semantic == graph::Semantic::HdrColor) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(120);
        ImGui::SliderFloat("EV", &v.params.exposure, -8.0f, 8.0f, "%.1f");
    }
}

void zoom_controls(ViewerState& v, const DecodedView& view) {
    ImGui::Text("zoom %.3gx", v.zoom);
    ImGui::SameLine();
    if (ImGui::SmallButton("1:1")) {
        v.zoom = 1.0f;
        v.centre = {0.5f, 0.5f};
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("fit") && view.width && view.height) {
        v.zoom = std::min(v.w / float(view.width), v.h / float(view.height));
        v.centre = {0.5f, 0.5f};
    }
    ImGui::SameLine();
    ImGui::Checkbox("samples", &v.sample_view);
    ImGui::SameLine();
    help_marker(
        "Zoomed in to 8x or more: each pixel's MSAA samples at their positions, coloured "
        "by the surface that holds each (the surface_id view's colours; dark blue: "
        "none). Hovering a pixel lists its samples: surface, depth, colour. Those frames "
        "turn surface_id on.");
}

// What the mouse drives over the image: the camera or the image's zoom and pan.
void mouse_mode(ViewerState& v) {
    int mouse = int(v.mouse);
    ImGui::TextUnformatted("  mouse:");
    ImGui::SameLine();
    ImGui::RadioButton("camera", &mouse, int(MouseTarget::Camera));
    ImGui::SameLine();
    ImGui::RadioButton("image", &mouse, int(MouseTarget::Image));
    ImGui::SameLine();
    ImGui::RadioButton("pick", &mouse, int(MouseTarget::Pick));
    v.mouse = MouseTarget(mouse);
    ImGui::SameLine();
    help_marker(
        "Camera: left drag orbits, middle drag pans, wheel dollies, right drag + WASD/QE flies "
        "(shift: faster; the speed scales with the scene's content), F frames the content.\nImage "
        "(or hold Ctrl): wheel zooms at the cursor, "
        "drag pans. Nearest-neighbour when zoomed in.\nPick (or Alt + click): a click lists "
        "every fragment of that pixel in the Pixel panel.");
}

// A small button on the toolbar's line, its tooltip when hovered; true when clicked.
bool tool_button(const char* label, const char* tip) {
    ImGui::SameLine();
    const bool clicked = ImGui::SmallButton(label);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
    return clicked;
}

// The camera's views, on the first row after the resource: frame (F), fit inside, the scene's
// camera and this scene's bookmarks (a popup; the Camera panel has them, and the scene's
// camera nodes, too).
void camera_controls(PanelIo& io) {
    ImGui::SameLine();
    ImGui::TextUnformatted("  camera:");
    if (tool_button("frame",
                    "The camera frames the scene's content (F): what a ground plane, "
                    "backdrop or sky dome many times larger than the rest leaves."))
        io.camera.frame = true;
    if (tool_button("fit inside",
                    "For interiors: the camera at an open spot inside the scene's bounds, "
                    "looking along their longest horizontal axis."))
        io.actions.push_back(FitInside{});
    if (tool_button("scene camera",
                    "Back to the scene's own camera (the file's first camera, "
                    "or the view depthscope framed when it has none; the command line's "
                    "--camera or --look-at when it chose one)."))
        io.actions.push_back(SceneCamera{});
    if (tool_button("bookmarks",
                    "Named views of this scene: add the current one, go to one, delete one "
                    "(kept between sessions; the Camera panel has them too)."))
        ImGui::OpenPopup("bookmarks");
    if (ImGui::BeginPopup("bookmarks")) {
        bookmark_list(io);
        ImGui::EndPopup();
    }
}

// The decode controls above the image, a row each: the resource (and the camera's views), its
// range and channel, the zoom and mouse mode.
void controls(PanelIo& io) {
    ViewerState& v = io.viewer;
    const InspectedImage* image = io.inspector.shown();
    const DecodedView& view = io.inspector.view();
    resource_picker(io, image);
    image_options(v, image);
    camera_controls(io);
    range_controls(v, view);
    channel_controls(v, image);
    zoom_controls(v, view);
    ImGui::SameLine();
    mouse_mode(v);
    ImGui::SameLine();
    if (ImGui::SmallButton("capture")) io.actions.push_back(CaptureFrame{});  // F12 too
    if (tool_button("diagnose",
                    "What is wrong with this view: every detector that applies, "
                    "ranked findings in the Diagnose panel."))
        io.actions.push_back(Diagnose{});
}

// A Scalar image's legend: its title over a colour bar (decode's colours from black to
// white), black's value at the bar's left, white's with the unit at its right.
void colour_bar(const ViewLegend& scale) {
    const graph::Display& d = *scale.display;
    ImGui::TextDisabled("%s", scale.label.c_str());
    ImGui::TextUnformatted(view::value_text(scale.black).c_str());
    ImGui::SameLine();
    const std::vector<LegendStop> stops = view::display_legend(d, scale.black, scale.white);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float width = 240.0f, height = ImGui::GetTextLineHeight();
    const float step = width / float(std::max<size_t>(stops.size(), 1));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    for (size_t i = 0; i < stops.size(); ++i) {
        const std::array<uint8_t, 3>& c = stops[i].rgb;
        draw->AddRectFilled(ImVec2(at.x + step * float(i), at.y),
                            ImVec2(at.x + step * float(i + 1), at.y + height),
                            IM_COL32(c[0], c[1], c[2], 255));
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::SameLine();
    std::string white = view::value_text(scale.white);
    if (!d.unit.empty()) white += " " + d.unit;
    if (d.scale == graph::ValueScale::Log) white += " (log)";
    ImGui::TextUnformatted(white.c_str());
}

// A heat map's legend: counts, or scene units on a log scale (depth_precision), after what
// shares it ("forward: counts, wasted"); a Scalar image's colour bar.
void legend(const ViewLegend& scale, int& id) {
    if (scale.display) return colour_bar(scale);
    const bool log_scale = scale.log;
    const std::vector<LegendStop> stops = log_scale ? view::log_legend(scale.black, scale.white)
                                                    : count_legend(scale.black, scale.white);
    ImGui::TextDisabled("%s", scale.label.c_str());
    ImGui::SameLine();
    for (const LegendStop& stop : stops) {
        const ImVec4 c(stop.rgb[0] / 255.0f, stop.rgb[1] / 255.0f, stop.rgb[2] / 255.0f, 1.0f);
        ImGui::PushID(id++);
        ImGui::ColorButton("##legend", c, ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
        ImGui::PopID();
        ImGui::SameLine();
        ImGui::Text(log_scale ? "%.2g m" : "%g", stop.count);
        ImGui::SameLine();
    }
    ImGui::NewLine();
}

// Mouse and keys over the image: camera input, or zoom and pan of the image.
void input(PanelIo& io, const ImVec2& origin, bool hovered, bool active) {
    ViewerState& v = io.viewer;
    const ImGuiIO& imgui = ImGui::GetIO();
    const DecodedView& view = io.inspector.view();
    const bool image_mode = v.mouse == MouseTarget::Image || imgui.KeyCtrl;
    CameraInput& cam = io.camera;
    if (v.mouse == MouseTarget::Pick) return;  // clicks pick (viewer_panel)
    if (image_mode) {
        if (hovered && imgui.MouseWheel != 0.0f && view.width) {
            // Zoom about the cursor: the texel under it stays under it.
            const float old_zoom = v.zoom;
            v.zoom = std::clamp(v.zoom * std::pow(1.25f, imgui.MouseWheel), 1.0f / 32, 64.0f);
            // v.w, v.h and the zoom are in framebuffer pixels, ImGui's mouse in its units.
            const ImVec2 fb = imgui.DisplayFramebufferScale;
            const glm::vec2 cursor{(imgui.MousePos.x - origin.x) * fb.x - 0.5f * v.w,
                                   (imgui.MousePos.y - origin.y) * fb.y - 0.5f * v.h};
            const glm::vec2 size{float(view.width), float(view.height)};
            v.centre += cursor * (1.0f / old_zoom - 1.0f / v.zoom) / size;
        }
        if (active && view.width &&
            (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0) ||
             ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0))) {
            const ImVec2 fb = imgui.DisplayFramebufferScale;
            v.centre.x -= imgui.MouseDelta.x * fb.x / (v.zoom * float(view.width));
            v.centre.y -= imgui.MouseDelta.y * fb.y / (v.zoom * float(view.height));
        }
        return;
    }
    if (hovered) cam.dolly += imgui.MouseWheel;
    if (active) {
        const glm::vec2 delta{imgui.MouseDelta.x, imgui.MouseDelta.y};
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) cam.orbit += delta;
        if (ImGui::IsMouseDown(ImGuiMouseButton_Middle)) cam.pan += delta;
        if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) cam.look += delta;
    }
    // Keys reach the camera unless a text field has them.
    if (imgui.WantTextInput) return;
    const bool flying = active && ImGui::IsMouseDown(ImGuiMouseButton_Right);
    if (flying) {
        // ImGui 1.86 indexes io.KeysDown by the backend's key codes: GLFW's are ASCII for
        // letters (the headless driver uses the same).
        auto key = [](char k) { return ImGui::IsKeyDown(int(k)) ? 1.0f : 0.0f; };
        cam.move += glm::vec3(key('D') - key('A'), key('E') - key('Q'), key('W') - key('S'));
        cam.fast = imgui.KeyShift;
    }
    if ((hovered || active) && ImGui::IsKeyPressed(int('F'), false)) cam.frame = true;
}

// The texel under the cursor: its readout and the overlays' values there; a click (not a
// drag) in pick mode or with Alt picks it for its pixel history.
std::optional<std::array<uint32_t, 2>> hover(PanelIo& io, bool hovered, ImVec2 scale) {
    ViewerState& v = io.viewer;
    v.hover.reset();
    v.hover_overlays.clear();
    if (!hovered || !io.inspector.view().width || !io.inspector.shown()) return std::nullopt;
    // Through the blit's own integer mapping: the readout names the texel drawn there.
    const ImGuiIO& imgui = ImGui::GetIO();
    const TargetSize target{uint32_t(imgui.DisplaySize.x * scale.x),
                            uint32_t(imgui.DisplaySize.y * scale.y)};
    const auto texel = texel_at(io.inspector.viewer_blit(), target, imgui.MousePos.x * scale.x,
                                imgui.MousePos.y * scale.y);
    if (!texel) return std::nullopt;
    v.hover = io.inspector.readout_at((*texel)[0], (*texel)[1]);
    v.hover_overlays = io.inspector.overlay_text((*texel)[0], (*texel)[1]);
    const bool pick = v.mouse == MouseTarget::Pick || imgui.KeyAlt;
    const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f);
    const bool click =
        drag.x * drag.x + drag.y * drag.y <= imgui.MouseDragThreshold * imgui.MouseDragThreshold;
    if (pick && click && ImGui::IsMouseReleased(ImGuiMouseButton_Left))
        io.actions.emplace_back(PickPixel{(*texel)[0], (*texel)[1]});
    return texel;
}

// The readout lines under the image.
void readout_lines(const ViewerState& v) {
    ImGui::Separator();
    if (v.hover)
        ImGui::Text("(%u, %u)  raw %s  |  %s", v.hover->x, v.hover->y, v.hover->raw_text.c_str(),
                    v.hover->decoded_text.c_str());
    else
        ImGui::TextDisabled("hover the image for pixel values");
    if (!v.overlays.empty()) {
        if (v.hover && !v.hover_overlays.empty())
            ImGui::Text("over it: %s", v.hover_overlays.c_str());
        else
            ImGui::TextDisabled("over it: %s",
                                counted(v.overlays.size(), "overlay", "overlays").c_str());
    }
}

// The image shown is the newest finished frame; while the next one renders, say so in the
// image's corner (the UI does not wait for it).
void rendering_mark(const Inspector& inspector, const ImVec2& origin) {
    if (!inspector.rendering()) return;
    char text[48];
    if (inspector.diagnosing())
        std::snprintf(text, sizeof text, "diagnosing... %.0f s", inspector.diagnosing_seconds());
    else
        std::snprintf(text, sizeof text, "rendering... %.0f ms", inspector.rendering_ms());
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 at(origin.x + 6, origin.y + 4);
    const ImVec2 size = ImGui::CalcTextSize(text);
    draw->AddRectFilled(ImVec2(at.x - 3, at.y - 1), ImVec2(at.x + size.x + 3, at.y + size.y + 1),
                        IM_COL32(0, 0, 0, 160));
    draw->AddText(at, IM_COL32(255, 220, 120, 255), text);
}

}  // namespace

// Inside the workspace's centre region (workspace_draw.cpp), which has no background: the
// presenter draws the image under ImGui at ViewerState x/y/w/h.
void viewer_panel(PanelIo& io) {
    ViewerState& v = io.viewer;
    const FrameResult& frame = io.inspector.frame();
    controls(io);
    int legend_id = 0;
    for (const ViewLegend& scale : io.inspector.composer().legends()) legend(scale, legend_id);
    if (!io.inspector.shown() && frame.width)
        ImGui::TextColored(ImVec4(1, 0.6f, 0.3f, 1), "'%s' is not in this frame (its pass is off)",
                           v.resource.c_str());

    // The image area: what is left above the readout lines (one more with overlays) and the
    // status line (always there: a capture must not change the render size).
    const float readout_height =
        ImGui::GetFrameHeightWithSpacing() * (v.overlays.empty() ? 3.0f : 4.0f);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImVec2 avail = ImGui::GetContentRegionAvail();
    avail.y = std::max(avail.y - readout_height, 1.0f);
    avail.x = std::max(avail.x, 1.0f);
    ImGui::InvisibleButton("##image", avail,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    const bool hovered = ImGui::IsItemHovered();
    const bool active = ImGui::IsItemActive();
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    v.x = origin.x * scale.x;
    v.y = origin.y * scale.y;
    v.w = std::floor(avail.x * scale.x);
    v.h = std::floor(avail.y * scale.y);
    input(io, origin, hovered, active);
    rendering_mark(io.inspector, origin);

    const auto texel = hover(io, hovered, scale);
    draw_samples(io, scale, texel);
    if (texel) sample_tooltip(io, (*texel)[0], (*texel)[1]);
    readout_lines(v);
    capture_status(io.inspector);
    if (io.inspector.compare().active(v.compare)) {
        ImGui::SameLine();
        ImGui::TextDisabled("|");
        ImGui::SameLine();
        compare_status(io.inspector, v.compare);
    }
    if (!io.inspector.message().empty())
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", io.inspector.message().c_str());
}

}  // namespace ds::ui
