// Overlays that stack, the shared count scale and the wasted view, through the inspector on
// lavapipe with validation: the renderer's list read-back, the composed pixels against
// decode's own heat colours, the overdraw scene's derived totals, the Overlays panel driven
// by actions and by ImGui input.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <imgui.h>

#include "capture/image_writer.h"
#include "renderer/scene/loader.h"
#include "renderer/view/heat.h"
#include "renderer/view/overlay.h"
#include "tests/gpu/passes/shared_renderer.h"
#include "ui/headless.h"

namespace ds::test {
namespace {

using ui::HeadlessInput;
using ui::HeadlessUi;
using Rgb = std::array<uint8_t, 3>;

class Overlays : public SharedRenderer {
  protected:
    std::unique_ptr<HeadlessUi> open(const std::string& scene_name, Settings settings = {},
                                     VkExtent2D size = {640, 360}) {
        scene::Scene scene = scene::load_scene(scene_name, settings);
        auto ui = std::make_unique<HeadlessUi>(*renderer_, settings, std::move(scene), size);
        ui->frame();
        return ui;
    }
    static const InspectedImage& image(const ui::Inspector& in, const std::string& name) {
        const InspectedImage* found = in.composer().find(in.frame(), name);
        EXPECT_TRUE(found) << name;
        static const InspectedImage none;
        return found ? *found : none;
    }
    static double sum(const InspectedImage& image) {
        double total = 0;
        for (size_t i = 0; i < image.texels.size(); i += 4) total += image.texels[i];
        return total;
    }
    static Rgb rgb(const std::vector<uint8_t>& rgba8, size_t texel) {
        return {rgba8[texel * 4], rgba8[texel * 4 + 1], rgba8[texel * 4 + 2]};
    }
    // The shared scale's top for `pass`: the largest count over the pass's count images
    // this frame read.
    static float pass_max(const ui::Inspector& in, const std::string& pass) {
        std::vector<const InspectedImage*> images;
        for (const InspectedImage& o : in.frame().overlays)
            if (const auto c = view::count_image_name(o.name); c && c->pass == pass)
                images.push_back(&o);
        if (in.frame().inspected && view::count_image_name(in.frame().inspected->name) &&
            view::count_image_name(in.frame().inspected->name)->pass == pass)
            images.push_back(&*in.frame().inspected);
        return view::count_max(images);
    }
};

uint8_t blend(uint8_t base, uint8_t over, double opacity) {
    return uint8_t(std::lround(double(base) + (double(over) - double(base)) * opacity));
}

// The list request reads every image the way a request of its own would, in order.
TEST_F(Overlays, TheInspectPassReadsEveryImageAsked) {
    const scene::Scene scene = scene::load_scene("atrium", Settings{});
    renderer_->set_scene(scene);
    const Settings s = settings_of({"count_fragments=on", "surface_id=on"});
    const std::vector<InspectRequest> request = {{.resource = "normals"},
                                                 {.resource = "forward_counts"},
                                                 {.resource = "no_such_image"},
                                                 {.resource = "surface_id"},
                                                 {.resource = "final"}};
    const FrameResult all = renderer_->render(
        scene.camera, s,
        {.width = 160, .height = 90, .read_back = ReadBack::No, .inspect = request});
    ASSERT_TRUE(all.inspected);
    EXPECT_EQ(all.inspected->name, "normals");
    ASSERT_EQ(all.overlays.size(), 2u) << "names the frame lacks and final are left out";
    EXPECT_EQ(all.overlays[0].name, "forward_counts");
    EXPECT_EQ(all.overlays[1].name, "surface_id");
    for (const InspectedImage& o : all.overlays) {
        const FrameResult alone =
            renderer_->render(scene.camera, s,
                              {.width = 160,
                               .height = 90,
                               .read_back = ReadBack::No,
                               .inspect = {InspectRequest{.resource = o.name}}});
        ASSERT_TRUE(alone.inspected);
        EXPECT_EQ(alone.inspected->texels, o.texels) << o.name;
        EXPECT_EQ(alone.inspected->semantic, o.semantic) << o.name;
    }
}

// A count image over the final image: at every texel, the heat colour of its count on the
// pass's shared scale blended with the opacity, where it counted; the final pixel elsewhere.
// A second overlay (another pass's counts) blends over the first.
TEST_F(Overlays, CountOverlaysBlendOverTheFinalImageInOrder) {
    auto ui = open("atrium", settings_of({"count_fragments=on", "prepass=off"}), {960, 540});
    ui::Inspector& in = ui->inspector();
    in.queue(ui::AddOverlay{"forward_counts"});
    in.queue(ui::AddOverlay{"decal_counts"});
    ui->frame();
    in.viewer().overlays[0].opacity = 0.6f;
    in.viewer().overlays[1].opacity = 0.3f;
    ui->frame();
    ASSERT_TRUE(in.frame().inspected);
    EXPECT_EQ(in.shown()->name, "final");
    const std::vector<uint8_t>& final_rgba = in.frame().rgba8;
    const InspectedImage& forward = image(in, "forward_counts");
    const InspectedImage& decals = image(in, "decal_counts");
    EXPECT_EQ(in.composer().overlay_status(), (std::vector<std::string>{"", ""}));
    const float forward_top = pass_max(in, "forward"), decals_top = pass_max(in, "decal");
    ASSERT_GT(forward_top, 1.0f) << "prepass off: some pixels shaded more than once";
    size_t zero = 0, both = 0;
    const size_t texels = size_t(forward.width) * forward.height;
    ASSERT_EQ(in.view().rgba8.size(), texels * 4);
    for (size_t t = 0; t < texels; ++t) {
        const float f = forward.texels[t * 4], d = decals.texels[t * 4];
        const Rgb base = rgb(final_rgba, t), shown = rgb(in.view().rgba8, t);
        const Rgb hf = view::count_color(f, 0, forward_top),
                  hd = view::count_color(d, 0, decals_top);
        for (size_t c = 0; c < 3; ++c) {
            int want = base[c];
            if (f > 0) want = blend(uint8_t(want), hf[c], 0.6);
            if (d > 0) want = blend(uint8_t(want), hd[c], 0.3);
            ASSERT_NEAR(int(shown[c]), want, 1) << "texel " << t << " channel " << c;
        }
        zero += f == 0 && d == 0;
        both += f > 0 && d > 0;
        if (f == 0 && d == 0) {
            ASSERT_EQ(shown, base) << "nothing counted is transparent";
        }
    }
    EXPECT_GT(zero, 0u) << "the sky shades nothing in forward";
    EXPECT_GT(both, 0u) << "decals lie over forward's walls";
    // Swapped, the second is under the first: the pixels where both counted change.
    const std::vector<uint8_t> before = in.view().rgba8;
    in.queue(ui::MoveOverlay{1, -1});
    ui->frame();
    EXPECT_EQ(in.viewer().overlays[0].resource, "decal_counts");
    ASSERT_EQ(in.view().rgba8.size(), before.size()) << "the same size";
    EXPECT_NE(in.view().rgba8, before);
    // A look at it: the Overlays panel open, forward's wasted view over the frame as well.
    in.queue(ui::AddOverlay{"forward_wasted"});
    in.workspace().select("Overlays");
    ui->frame();
    const std::vector<uint8_t> pixels = ui->frame();
    EXPECT_EQ(in.composer().overlay_status(), (std::vector<std::string>{"", "", ""}));
    if (const char* png = std::getenv("DS_OVERLAYS_PNG"))
        capture::write_png_rgba8(png, ui->size().width, ui->size().height, pixels);
}

// The overdraw scene, N layers over every pixel: forward's wasted view sums to (N - 1) W H
// without the prepass and to 0 with it; the prepass's own waste depends on its sort.
TEST_F(Overlays, WastedOnTheOverdrawSceneIsTheHiddenLayers) {
    auto ui = open("overdraw", settings_of({"count_fragments=on", "prepass=off"}));
    ui::Inspector& in = ui->inspector();
    const double n = double(in.scene_summary().opaque);
    ASSERT_GE(n, 2.0);
    const std::vector<std::string> listed = in.viewable();
    const auto at = [&](const std::string& name) {
        return std::find(listed.begin(), listed.end(), name) - listed.begin();
    };
    ASSERT_LT(at("forward_wasted"), long(listed.size()));
    EXPECT_EQ(at("forward_wasted"), at("forward_rasterized") + 1) << "after the pass's counts";
    in.queue(ui::SelectResource{"forward_wasted"});
    ui->frame();
    ASSERT_TRUE(in.shown());
    // W x H of this frame: the viewer's area (a legend line takes some of it) changes it.
    const auto pixels = [&] { return double(in.shown()->width) * in.shown()->height; };
    EXPECT_EQ(in.shown()->name, "forward_wasted");
    EXPECT_EQ(sum(*in.shown()), (n - 1) * pixels());
    const std::string text = in.readout_at(3, 4)->decoded_text;
    char want[64];
    std::snprintf(want, sizeof want, "shaded %.0f, covered 1, wasted %.0f", n, n - 1);
    EXPECT_EQ(text, want);
    ASSERT_EQ(in.composer().legends().size(), 1u);
    EXPECT_EQ(in.composer().legends()[0].label, "forward: wasted");
    if (const char* png = std::getenv("DS_WASTED_PNG")) {  // a look, hovering the image
        HeadlessInput hover;
        hover.mouse = glm::vec2(in.viewer().x + 40.0f, in.viewer().y + 40.0f);
        ui->frame(hover);
        capture::write_png_rgba8(png, ui->size().width, ui->size().height, ui->frame(hover));
    }

    in.queue(ui::SetSetting{"prepass", "on"});
    ui->frame();
    EXPECT_EQ(sum(*in.shown()), 0.0);
    in.queue(ui::SelectResource{"prepass_wasted"});
    ui->frame();
    ASSERT_TRUE(in.shown());
    EXPECT_EQ(sum(*in.shown()), 0.0) << "front to back: one prepass fragment per pixel";
    in.queue(ui::SetSetting{"prepass_sort", "off"});
    ui->frame();
    EXPECT_EQ(sum(*in.shown()), (n - 1) * pixels()) << "authored order: every layer";
    // As an overlay over the final image it is drawn like any count image.
    in.queue(ui::SelectResource{"final"});
    in.queue(ui::AddOverlay{"prepass_wasted"});
    ui->frame();
    EXPECT_EQ(in.composer().overlay_status(), (std::vector<std::string>{""}));
    EXPECT_NE(in.overlay_text(3, 4).find("prepass_wasted: shaded"), std::string::npos)
        << in.overlay_text(3, 4);
}

// The shared scale: one pass's count images decode on 0..max over all of them, with one
// legend; unshared, each fits its own.
TEST_F(Overlays, APassesCountImagesShareOneScaleAndLegend) {
    // foliage without the prepass: forward's masked pipeline discards, so forward_discarded's
    // max is below forward_counts'.
    auto ui = open("foliage", settings_of({"count_fragments=on", "prepass=off"}));
    ui::Inspector& in = ui->inspector();
    in.queue(ui::SelectResource{"forward_discarded"});
    ui->frame();
    const float own = view::count_max(std::vector<const InspectedImage*>{in.shown()});
    const float shared = pass_max(in, "forward");
    const InspectedImage* counts = in.composer().find(in.frame(), "forward_counts");
    const InspectedImage* rasterized = in.composer().find(in.frame(), "forward_rasterized");
    ASSERT_TRUE(counts && rasterized) << "the pass's other images are read for the scale";
    EXPECT_EQ(
        shared,
        std::max(own, view::count_max(std::vector<const InspectedImage*>{counts, rasterized})));
    ASSERT_GT(shared, own);
    EXPECT_EQ(in.view().black, 0.0f);
    EXPECT_EQ(in.view().white, shared);
    in.queue(ui::AddOverlay{"forward_counts"});
    ui->frame();
    ASSERT_EQ(in.composer().legends().size(), 1u) << "drawn once for the pass";
    EXPECT_EQ(in.composer().legends()[0].label, "forward: discarded, counts");
    // This frame's (the legend line changed the viewer's size, so the counts changed too).
    EXPECT_EQ(in.composer().legends()[0].white, pass_max(in, "forward"));

    in.viewer().shared_count_scale = false;
    ui->frame();
    // Its own range again (of this frame: the viewer's size, and with it the counts, follow
    // the legend lines).
    EXPECT_EQ(in.view().white, view::count_max(std::vector<const InspectedImage*>{in.shown()}));
    EXPECT_LT(in.view().white, pass_max(in, "forward"));
    EXPECT_EQ(in.composer().legends().size(), 2u);
    // A manual range in the viewer is the pass's scale.
    in.viewer().shared_count_scale = true;
    in.viewer().params.auto_fit = false;
    in.viewer().params.black = 0.0f;
    in.viewer().params.white = 2.0f;
    ui->frame();
    ASSERT_EQ(in.composer().legends().size(), 1u);
    EXPECT_EQ(in.composer().legends()[0].white, 2.0f);
}

// The panel: actions edit the list; a click on a row's checkbox hides that overlay (real
// ImGui input at the row's place in the window).
TEST_F(Overlays, ThePanelEditsTheList) {
    auto ui = open("overdraw", settings_of({"count_fragments=on", "surface_id=on"}));
    ui::Inspector& in = ui->inspector();
    in.queue(ui::AddOverlay{"surface_id"});
    in.queue(ui::AddOverlay{"forward_counts"});
    in.queue(ui::AddOverlay{"depth"});
    ui->frame();
    ASSERT_EQ(in.viewer().overlays.size(), 3u);
    in.queue(ui::MoveOverlay{2, -1});
    in.queue(ui::MoveOverlay{0, -1});  // already first: nothing
    in.queue(ui::RemoveOverlay{0});
    in.queue(ui::RemoveOverlay{9});  // no such row: nothing
    ui->frame();
    ASSERT_EQ(in.viewer().overlays.size(), 2u);
    EXPECT_EQ(in.viewer().overlays[0].resource, "depth");
    EXPECT_EQ(in.viewer().overlays[1].resource, "forward_counts");

    in.workspace().select("Overlays");
    in.workspace().set_splits({0, 0, 300});  // a strip tall enough for the rows (clamped)
    ui->frame();
    ui->frame();
    ASSERT_TRUE(in.workspace().panel_rects().count("Overlays"));
    const ui::Rect panel = in.workspace().panel_rects().at("Overlays");
    const ImGuiStyle& style = ImGui::GetStyle();
    const float frame_h = ImGui::GetFrameHeight();
    // Row 0 holds the add picker; overlay i is row i + 1.
    const glm::vec2 checkbox{panel.x + frame_h * 0.5f,
                             panel.y + 2 * (frame_h + style.ItemSpacing.y) + frame_h * 0.5f};
    HeadlessInput press;
    press.mouse = checkbox;
    press.left = true;
    ui->frame(press);
    HeadlessInput release;
    release.mouse = checkbox;
    ui->frame(release);
    EXPECT_TRUE(in.viewer().overlays[0].visible);
    EXPECT_FALSE(in.viewer().overlays[1].visible) << "the second row's checkbox";
    ui->frame();
    EXPECT_EQ(in.composer().overlay_status()[1], "hidden");
    // An image of another size (the shadow map) is listed and not drawn.
    in.queue(ui::AddOverlay{"shadow_map"});
    ui->frame();
    EXPECT_EQ(in.composer().overlay_status()[2], "size differs");
    // Hovering the image reads the drawn overlays there too.
    const ui::ViewerState& v = in.viewer();
    HeadlessInput hover;
    hover.mouse = glm::vec2(v.x + v.w * 0.5f, v.y + v.h * 0.4f);
    ui->frame(hover);
    ASSERT_TRUE(v.hover);
    EXPECT_EQ(v.hover_overlays.rfind("depth: linear depth 2.0", 0), 0u) << v.hover_overlays;
    EXPECT_EQ(v.hover_overlays.find("forward_counts"), std::string::npos) << "hidden";
}

}  // namespace
}  // namespace ds::test

namespace ds::test {
namespace {

// Not a timed test (run it by name with --gtest_also_run_disabled_tests): what each overlay
// costs at 1280x720 on the device — the inspect pass and its read-back per extra image, and
// the CPU side of the viewer (decode and blend).
TEST_F(Overlays, DISABLED_CostPerOverlay) {
    // One layer of the overdraw scene without the prepass (and the AO it feeds): a cheap frame, so
    // the differences stand out of the noise (the inspect pass's work does not depend on the
    // scene).
    const Settings s = settings_of({"count_fragments=on", "prepass=off", "overdraw_layers=1"});
    const scene::Scene scene = scene::load_scene("overdraw", s);
    renderer_->set_scene(scene);
    const std::vector<InspectRequest> all = {{.resource = "final"},
                                             {.resource = "forward_counts"},
                                             {.resource = "forward_discarded"},
                                             {.resource = "depth"},
                                             {.resource = "hdr"}};
    auto ms_of = [](const FrameResult& f, const std::string& name) {
        double ms = 0;
        for (const PassResult& p : f.passes)
            if (p.name == name) ms += p.gpu_ms;
        return ms;
    };
    // Lavapipe takes timestamps when it flushes rasterisation, so a compute pass between two
    // reads ~0 ms: the cost is the render call's wall time with n images against 1, the
    // configurations interleaved so that a shared CPU's drift falls on all of them.
    std::vector<std::vector<double>> wall(all.size());
    std::vector<std::vector<double>> inspect_ms(all.size());
    for (int round = 0; round < 15; ++round) {
        for (size_t n = 1; n <= all.size(); ++n) {
            const auto start = std::chrono::steady_clock::now();
            const FrameResult f = renderer_->render(scene.camera, s,
                                                    {.width = 1280,
                                                     .height = 720,
                                                     .read_back = ReadBack::No,
                                                     .inspect = {all.begin(), all.begin() + n}});
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            ASSERT_EQ(f.overlays.size(), n - 1);
            if (round < 2) continue;  // warm-up
            wall[n - 1].push_back(ms);
            inspect_ms[n - 1].push_back(ms_of(f, "inspect") + ms_of(f, "readback_inspect"));
        }
    }
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    const double none = median(wall[0]);
    for (size_t n = 1; n <= all.size(); ++n)
        std::printf(
            "overlays %zu: render %.1f ms wall (%+.1f against none), inspect + "
            "readback_inspect %.2f GPU ms (medians)\n",
            n - 1, median(wall[n - 1]), median(wall[n - 1]) - none, median(inspect_ms[n - 1]));
    const FrameResult f = renderer_->render(
        scene.camera, s,
        {.width = 1280, .height = 720, .read_back = ReadBack::No, .inspect = {all[1]}});
    ASSERT_TRUE(f.inspected);
    view::DecodedView base = view::decode(*f.inspected, view::ViewParams{}), over;
    const auto start = std::chrono::steady_clock::now();
    constexpr int kRuns = 10;
    for (int i = 0; i < kRuns; ++i) {
        view::decode_into(*f.inspected, view::ViewParams{}, over);
        view::blend_overlay(base, over, *f.inspected, 0.5f);
    }
    const double cpu =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count() /
        kRuns;
    std::printf("CPU decode + blend of one count overlay at 1280x720: %.2f ms\n", cpu);
}

}  // namespace
}  // namespace ds::test
