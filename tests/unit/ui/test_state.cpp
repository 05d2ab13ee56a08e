// State follows the scene (issue 24 point 1), offscreen through the inspector's own actions on
// lavapipe with validation: a pick is rendered again under new settings and dropped by a new
// scene or render size; a selected Z-fight pair is found again by its surfaces; and a random
// sequence of actions across scene switches leaves no index into a previous scene's tables.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "renderer/passes/draw_counts.h"
#include "renderer/passes/pixel_history.h"
#include "renderer/passes/zfight.h"
#include "tests/unit/ui/inspector_ui.h"

namespace ds::test {
namespace {

class InspectorState : public InspectorUi {};

// What must hold after any action: a pick is of this scene and its instances exist here; the
// selected pair and draw index the shown frame's and this scene's tables.
void expect_consistent(ui::Inspector& in, const std::string& step) {
    SCOPED_TRACE(step);
    const scene::Scene& scene = in.scene();
    if (in.pixel_history()) {
        EXPECT_EQ(in.pixel_label().rfind(scene.name + " at ", 0), 0u) << in.pixel_label();
        for (const PixelFragment& f : in.pixel_history()->fragments)
            EXPECT_LT(f.instance, scene.instances.size());
    }
    if (in.viewer().zfight_pair >= 0) {
        const ZfightResult* z = in.frame().find<ZfightResult>();
        ASSERT_TRUE(z);
        EXPECT_LT(size_t(in.viewer().zfight_pair), z->pairs.size());
    }
    if (in.viewer().draw >= 0) {
        EXPECT_LT(size_t(in.viewer().draw), scene.draw_groups.size());
    }
    if (in.viewer().finding >= 0) {  // a finding of this scene's diagnosis
        ASSERT_TRUE(in.diagnosis());
        EXPECT_LT(size_t(in.viewer().finding), in.diagnosis()->findings.size());
        EXPECT_EQ(in.diagnosis()->scene, scene.name);
    }
    if (in.diagnosis()) {
        EXPECT_EQ(in.diagnosis()->scene, scene.name);
    }
    const std::vector<uint8_t> mask = in.selected_finding_pixels();
    EXPECT_TRUE(mask.empty() || mask.size() == size_t(in.frame().width) * in.frame().height);
}

// A pick follows the settings (the same pixel, rendered again: alpha_cutoff changes what the
// foliage's masked prepass discards there) and is dropped by a new render size.
TEST_F(InspectorState, APickFollowsTheSettingsAndIsDroppedByANewSize) {
    auto ui = open("foliage", {}, {960, 540});
    ui::Inspector& in = ui->inspector();
    const VkExtent2D size = in.render_size();
    in.queue(ui::PickPixel{size.width / 2, size.height / 2});
    ui->frame();
    ASSERT_TRUE(in.pixel_history()) << in.pixel_error();
    auto discarded = [&] {
        size_t n = 0;
        for (const PixelFragment& f : in.pixel_history()->fragments)
            n += f.alpha_test && !f.alpha_test->passed;
        return n;
    };
    const size_t before = discarded();
    in.queue(ui::SetSetting{"alpha_cutoff", "1"});  // every alpha below 1 is cut
    ui->frame();
    ASSERT_TRUE(in.pixel_history()) << in.pixel_error();
    EXPECT_GT(discarded(), before) << "the history was not rendered again";
    in.queue(ui::SetSetting{"render_scale", "0.5"});
    ui->frame();
    EXPECT_FALSE(in.pixel_history()) << "a pick of another size names another point";
}

// The Depth panel's selected pair is found again by its surfaces in each new frame: select,
// in the d32f frame, a pair whose place differs in the d16 frame (or that is not there: a d16
// step is far coarser, so more surfaces fight), then switch to d16.
TEST_F(InspectorState, TheSelectedPairIsFoundAgainByItsSurfaces) {
    auto ui = open("zfight", {}, {960, 540});
    ui::Inspector& in = ui->inspector();
    auto pairs = [&] {
        const ZfightResult* z = in.frame().find<ZfightResult>();
        return z ? z->pairs : std::vector<ZfightPair>{};
    };
    auto index_in = [](const std::vector<ZfightPair>& list, const ZfightPair& p) {
        for (size_t i = 0; i < list.size(); ++i)
            if (list[i].a == p.a && list[i].b == p.b) return int(i);
        return -1;
    };
    in.queue(ui::SetSetting{"zfight", "on"});
    in.queue(ui::SetSetting{"depth_format", "d16"});
    ui->frame();
    const std::vector<ZfightPair> d16 = pairs();
    in.queue(ui::SetSetting{"depth_format", "d32f"});
    ui->frame();
    const std::vector<ZfightPair> d32 = pairs();
    int chosen = -1;
    for (size_t i = 0; i < d32.size() && chosen < 0; ++i)
        if (index_in(d16, d32[i]) != int(i)) chosen = int(i);
    ASSERT_GE(chosen, 0) << "every pair keeps its place: the test would prove nothing";
    in.viewer().zfight_pair = chosen;
    in.queue(ui::SetSetting{"depth_format", "d16"});
    ui->frame();
    const std::vector<ZfightPair> again = pairs();
    const int expected = index_in(again, d32[size_t(chosen)]);
    EXPECT_EQ(in.viewer().zfight_pair, expected);
    if (expected >= 0) {
        EXPECT_EQ(again[size_t(expected)].a, d32[size_t(chosen)].a);
    }
}

// Random actions in random order across scene switches (a fixed seed, so a failure repeats):
// nothing throws, and no pick, selection or diagnosis outlives what it indexes.
TEST_F(InspectorState, RandomActionsAcrossSceneSwitchesKeepStateConsistent) {
    auto ui = open("atrium", {}, {480, 270});
    ui::Inspector& in = ui->inspector();
    std::mt19937 rng(23);
    const std::vector<std::string> scenes = {"atrium", "foliage", "zfight", "decals", "overdraw"};
    const std::vector<ui::SetSetting> sets = {
        {"zfight", "on"},      {"zfight", "off"},       {"count_draws", "on"},
        {"msaa", "4"},         {"msaa", "1"},           {"alpha_cutoff", "0.2"},
        {"render_scale", "1"}, {"render_scale", "0.5"}, {"overdraw_layers", "3"}};
    auto pick = [&](size_t n) { return size_t(rng() % n); };
    int selected = 0;  // steps that ended with a finding selected
    for (int step = 0; step < 40; ++step) {
        std::string what;
        switch (pick(8)) {
            case 0:
                what = "scene " + scenes[pick(scenes.size())];
                in.queue(ui::LoadScene{what.substr(6)});
                break;
            case 1: {
                const ui::SetSetting& s = sets[pick(sets.size())];
                what = s.name + "=" + s.value;
                in.queue(s);
                break;
            }
            case 2: {
                const VkExtent2D size = in.render_size();
                const uint32_t x = uint32_t(pick(size.width)), y = uint32_t(pick(size.height));
                what = "pick " + std::to_string(x) + "," + std::to_string(y);
                in.queue(ui::PickPixel{x, y});
                break;
            }
            case 3: {
                const ZfightResult* z = in.frame().find<ZfightResult>();
                in.viewer().zfight_pair = z && !z->pairs.empty() ? int(pick(z->pairs.size())) : -1;
                what = "pair " + std::to_string(in.viewer().zfight_pair);
                break;
            }
            case 4: {
                const auto& draws = passes::draws_of(in.frame()).draws;
                in.viewer().draw = draws.empty() ? -1 : int(pick(draws.size()));
                what = "draw " + std::to_string(in.viewer().draw);
                break;
            }
            case 5:  // rarely: a diagnosis takes a few frames' time
                if (pick(3) == 0) {
                    what = "diagnose";
                    in.queue(ui::Diagnose{});
                }
                break;
            case 6: {  // any index, valid or not
                const int index = int(pick(12)) - 1;
                what = "finding " + std::to_string(index);
                in.queue(ui::SelectFinding{index});
                break;
            }
            default: {
                const std::vector<std::string> names = in.viewable();
                what = "view " + names[pick(names.size())];
                in.queue(ui::SelectResource{what.substr(5)});
            }
        }
        ASSERT_NO_THROW(ui->frame()) << "step " << step << ": " << what;
        expect_consistent(in, "step " + std::to_string(step) + ": " + what);
        selected += in.viewer().finding >= 0;
    }
    EXPECT_GT(selected, 0) << "the seed's actions never selected a finding: no test of it";
    EXPECT_EQ(renderer_->validation_message_count(), 0u);
}

}  // namespace
}  // namespace ds::test
