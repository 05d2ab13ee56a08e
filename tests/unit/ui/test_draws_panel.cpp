// The Draws panel in the inspector, offscreen on lavapipe with validation: the action it
// queues, its sort and filter (draw_rows, and the rows it drew), and the viewer's highlight
// of the selected draw.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "capture/image_writer.h"
#include "renderer/passes/draw_counts.h"
#include "renderer/scene/loader.h"
#include "tests/gpu/passes/shared_renderer.h"
#include "ui/headless.h"
#include "ui/panels/panels.h"

namespace ds::test {
namespace {

using ui::HeadlessUi;

class DrawsPanel : public SharedRenderer {};

// The Draws panel: off, it offers count_draws (the action it queues turns it on); on, its
// rows filter by name and sort by every numeric column; selecting a draw keeps exactly its
// pixels (surface_id's winner in its group) bright in the viewer and dims the rest.
TEST_F(DrawsPanel, FiltersSortsAndHighlightsTheSelectedDraw) {
    HeadlessUi ui_owner(*renderer_, Settings{}, scene::load_scene("atrium", Settings{}),
                        {640, 360});
    HeadlessUi* ui = &ui_owner;
    ui->frame();  // lays the panels out
    ui::Inspector& in = ui->inspector();
    in.workspace().select("Draws");
    in.workspace().set_splits({0, 0, 300});  // room for the summary, the filter and the table
    ui->frame();
    EXPECT_TRUE(passes::draws_of(in.frame()).draws.empty());
    in.queue(ui::SetSetting{"count_draws", "on"});
    in.queue(ui::SetSetting{"hiz", "on"});       // the Hi-Z column has verdicts to sort
    in.queue(ui::SelectResource{"surface_id"});  // the same from frame to frame (no history)
    ui->frame();
    ui->frame();  // the panels draw the last frame's results: now the counted one
    const FrameResult& f = in.frame();
    ASSERT_FALSE(passes::draws_of(f).draws.empty());
    EXPECT_EQ(in.panel_state().draw_rows.size(),
              passes::draws_of(f).draws.size());  // drawn, unfiltered
    for (const DrawReport& d : passes::draws_of(f).draws)
        EXPECT_TRUE(d.hiz.has_value()) << d.name.mesh;

    // Sorting: each numeric column orders its measured values, nulls last.
    for (int column = ui::kDrawInstances; column < ui::kDrawShaded + 4; ++column) {
        for (bool ascending : {true, false}) {
            const std::vector<size_t> rows =
                ui::draw_rows(passes::draws_of(f).draws, "", column, ascending);
            ASSERT_EQ(rows.size(), passes::draws_of(f).draws.size());
            auto value = [&](size_t i) -> std::optional<int64_t> {
                const DrawReport& d = passes::draws_of(f).draws[i];
                switch (column) {
                    case ui::kDrawInstances:
                        return d.instances;
                    case ui::kDrawVisible:
                        return d.visible_pixels;
                    case ui::kDrawSamples:
                        return d.samples_passed;
                    case ui::kDrawHiz:
                        return d.hiz ? std::optional<int64_t>(int64_t(*d.hiz)) : std::nullopt;
                    case ui::kDrawWasted: {
                        if (d.wasted_fragments.empty()) return std::nullopt;
                        int64_t sum = 0;
                        for (const auto& w : d.wasted_fragments) sum += w.second;
                        return sum;
                    }
                    default:
                        return d.shaded_fragments.at(size_t(column - ui::kDrawShaded)).second;
                }
            };
            for (size_t r = 1; r < rows.size(); ++r) {
                const auto a = value(rows[r - 1]), b = value(rows[r]);
                if (!a) {
                    EXPECT_FALSE(b) << column;
                } else if (b) {
                    EXPECT_TRUE(ascending ? *a <= *b : *a >= *b) << column;
                }
            }
        }
    }
    // Filtering by a node name keeps the draws whose mesh, material or node contains it.
    const std::string node = passes::draws_of(f).draws.back().name.node;
    std::snprintf(in.panel_state().draw_filter.data(), in.panel_state().draw_filter.size(), "%s",
                  node.c_str());
    ui->frame();

    ASSERT_FALSE(in.panel_state().draw_rows.empty());
    EXPECT_LT(in.panel_state().draw_rows.size(), passes::draws_of(f).draws.size());
    for (size_t i : in.panel_state().draw_rows) {
        const SurfaceName& n = passes::draws_of(in.frame()).draws[i].name;
        EXPECT_TRUE((n.mesh + n.material + n.node).find(node) != std::string::npos) << n.node;
    }
    in.panel_state().draw_filter[0] = '\0';

    // Selection: the draw with the most visible pixels stays as it was, another one dims.
    const FrameResult& g = in.frame();
    size_t best = 0;
    for (size_t i = 0; i < passes::draws_of(g).draws.size(); ++i)
        if (passes::draws_of(g).draws[i].visible_pixels.value_or(0) >
            passes::draws_of(g).draws[best].visible_pixels.value_or(0))
            best = i;
    ASSERT_GT(passes::draws_of(g).draws[best].visible_pixels.value_or(0), 0u);
    auto first_pixel = [&](auto pred) {
        for (size_t p = 0; p < passes::draws_of(g).draw_pixels.size(); ++p)
            if (pred(passes::draws_of(g).draw_pixels[p])) return p;
        ADD_FAILURE() << "no such pixel";
        return size_t(0);
    };
    const size_t mine = first_pixel([&](uint32_t d) { return d == best + 1; });
    const size_t other = first_pixel([&](uint32_t d) { return d != best + 1; });
    auto colour = [&](size_t pixel) {
        const auto& v = in.view();
        return std::vector<uint8_t>(v.rgba8.begin() + pixel * 4, v.rgba8.begin() + pixel * 4 + 3);
    };
    ui->frame();  // the same frame again, unselected
    const auto mine_before = colour(mine), other_before = colour(other);
    in.viewer().draw = int(best);
    ui->frame();
    EXPECT_EQ(in.selected_draw_pixels().size(), passes::draws_of(in.frame()).draw_pixels.size());
    EXPECT_EQ(colour(mine), mine_before);
    EXPECT_NE(colour(other), other_before);
    for (size_t c = 0; c < 3; ++c) EXPECT_LE(colour(other)[c], other_before[c]);
    if (const char* png = std::getenv("DS_DRAWS_PNG")) {
        in.queue(ui::SelectResource{"final"});
        ui->frame();
        capture::write_png_rgba8(png, 640, 360, ui->frame());
    }
}

}  // namespace
}  // namespace ds::test
