// Tiler: seed 002's view of the frame. On render_path=subpass, the render pass's attachments
// (load and store, transient or stored, and whether tile memory is lazily allocated), the tile
// budget (colour bits per pixel against 128 and 256) and the merge conditions one by one with
// the verdict. On the dynamic path, a button that switches to the subpass path.
#include <cstdio>

#include <imgui.h>

#include "renderer/settings/frame_knobs.h"
#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

const ImVec4 kGood(0.5f, 1.0f, 0.5f, 1.0f);
const ImVec4 kBad(1.0f, 0.6f, 0.3f, 1.0f);

void budget(const graph::TilerReport& t) {
    ImGui::Text("tile colour: %u bits per sample x %u = %u bits per pixel", t.bits_per_pixel,
                t.samples, t.tile_bits_per_pixel);
    ImGui::SameLine();
    help_marker(
        "seed 002: most Mali GPUs keep 128 bits of colour per pixel in a 16x16 tile, some 256; "
        "more makes the tiles smaller. Colour and input attachments count; depth and resolve "
        "destinations (memory) do not.");
    for (const uint32_t limit : {128u, 256u}) {
        char label[48];
        std::snprintf(label, sizeof label, "%u / %u", t.tile_bits_per_pixel, limit);
        const bool fits = t.tile_bits_per_pixel <= limit;
        ImGui::PushStyleColor(ImGuiCol_PlotHistogram, fits ? kGood : kBad);
        ImGui::ProgressBar(float(t.tile_bits_per_pixel) / float(limit), ImVec2(-1, 0), label);
        ImGui::PopStyleColor();
    }
}

void attachments(const graph::TilerReport& t) {
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("attachments", 7, flags, ImVec2(table_fit_width("attachments"), 0)))
        return;
    for (const char* h : {"#", "attachment", "format", "role", "bits", "load / store", "memory"})
        ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    int index = 0;
    for (const graph::TilerAttachment& a : t.attachments) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%d", index++);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(a.name.c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%s x%u", a.format.c_str(), a.samples);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(a.role.c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%u", a.bits);
        ImGui::TableNextColumn();
        ImGui::Text("%s / %s", a.load.c_str(), a.store.c_str());
        ImGui::TableNextColumn();
        if (!a.transient)
            ImGui::TextDisabled("stored");
        else if (a.lazily_allocated)
            ImGui::TextColored(kGood, "transient, lazily allocated");
        else
            ImGui::TextDisabled("transient (no lazy memory on this device)");
    }
    ImGui::EndTable();
}

void conditions(const graph::TilerReport& t) {
    for (const graph::TilerCondition& c : t.conditions) {
        ImGui::TextColored(c.ok ? kGood : kBad, "%s", c.ok ? "yes" : "no ");
        ImGui::SameLine();
        ImGui::Text("%s", c.name.c_str());
        ImGui::SameLine();
        ImGui::TextDisabled("%s", c.detail.c_str());
    }
    ImGui::TextColored(t.mergeable ? kGood : kBad, "%s", t.verdict.c_str());
}

}  // namespace

void tiler_panel(PanelIo& io) {
    const FrameResult& frame = io.inspector.frame();
    if (!frame.tiler) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled(
            "render_path=dynamic: every pass renders on its own, nothing for a tiler to merge.");
        if (ImGui::Button("render_path=subpass"))
            io.actions.push_back(SetSetting{knobs::kRenderPath.name, "subpass"});
        ImGui::SameLine();
        help_marker(
            "seed 002: depth prepass, forward and sky as two subpasses of one render pass; "
            "forward reads normals and roughness as input attachments (tile memory). Needs the "
            "prepass; gtao, contact_shadows and per-pass diagnostics do not run on it.");
        ImGui::PopTextWrapPos();
    } else {  // no wrapping: it would squeeze the table's columns
        const graph::TilerReport& t = *frame.tiler;
        ImGui::Text("render pass '%s': %u subpasses", t.group.c_str(), t.subpasses);
        budget(t);
        attachments(t);
        conditions(t);
    }
}

}  // namespace ds::ui
