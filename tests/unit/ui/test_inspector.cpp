// The inspector driven programmatically, offscreen (ui::HeadlessUi: the window's code with the
// input fed by the test), on lavapipe with validation: actions a panel returns, and real mouse
// input through ImGui (hover readout, camera orbit, image zoom).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include <imgui.h>

#include "capture/image_writer.h"
#include "renderer/passes/depth_prepass.h"
#include "renderer/passes/zfight.h"
#include "renderer/scene/loader.h"
#include "tests/gpu/passes/shared_renderer.h"
#include "tests/unit/ui/inspector_ui.h"
#include "ui/config.h"
#include "ui/headless.h"
#include "ui/shader_watch.h"

namespace ds::test {
namespace {

using ui::HeadlessInput;

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}
using ui::HeadlessUi;

class Inspector : public InspectorUi {
  protected:
    static bool has_pass(const FrameResult& f, const std::string& name) {
        return std::any_of(f.passes.begin(), f.passes.end(),
                           [&](const PassResult& p) { return p.name == name; });
    }
};

TEST_F(Inspector, EveryPanelHasDataAfterTheFirstFrames) {
    auto ui = open("atrium");
    const std::vector<uint8_t> pixels = ui->frame();
    ASSERT_EQ(pixels.size(), size_t(960) * 540 * 4);
    const FrameResult& f = ui->inspector().frame();
    // "final" is read back as is: no inspect pass, the eleven frame passes and readback_final.
    EXPECT_EQ(names(f).size(), 11u);
    for (const PassResult& p : f.passes) EXPECT_GT(p.gpu_ms, 0.0) << p.name;
    EXPECT_GE(f.resources.size(), 14u);
    ASSERT_TRUE(f.inspected);
    EXPECT_EQ(f.inspected->name, "final");
    // The scene renders at the viewer's area, smaller than the UI.
    const VkExtent2D size = ui->inspector().render_size();
    EXPECT_EQ(f.width, size.width);
    EXPECT_LT(f.width, 960u);
    EXPECT_GT(ui->last_stats().gpu_ms, 0.0);
}

TEST_F(Inspector, SelectingAResourceShowsItDecoded) {
    auto ui = open("atrium");
    ui->inspector().queue(ui::SelectResource{"normals"});
    ui->frame();
    const FrameResult& f = ui->inspector().frame();
    ASSERT_TRUE(f.inspected);
    EXPECT_EQ(f.inspected->name, "normals");
    EXPECT_EQ(f.inspected->semantic, graph::Semantic::EncodedNormal);
    EXPECT_TRUE(has_pass(f, "inspect"));
    EXPECT_EQ(ui->inspector().view().width, f.width);
    // Every resource of the frame can be shown, multisampled ones included.
    ui->inspector().queue(ui::SetSetting{"msaa", "4"});
    ui->frame();
    const std::vector<ResourceSummary> resources = ui->inspector().frame().resources;  // a copy
    for (const ResourceSummary& r : resources) {
        if (!r.is_image) continue;
        ui->inspector().queue(ui::SelectResource{r.name});
        ui->frame();
        const auto& shown = ui->inspector().frame().inspected;
        ASSERT_TRUE(shown) << r.name;
        EXPECT_EQ(shown->name, r.name);
        EXPECT_EQ(shown->width, r.width) << r.name;
        EXPECT_EQ(ui->inspector().view().rgba8.size(), size_t(r.width) * r.height * 4) << r.name;
    }
}

// prepass_mode=depth (issue 14): the resource list is the graph's, so the G-buffer images are
// simply not there; a viewer left on "normals" shows nothing and says nothing wrong; every
// resource that is listed decodes, the reconstructed depth_normals included.
TEST_F(Inspector, DepthPrepassModeListsOnlyItsOwnResources) {
    auto ui = open("atrium");
    ui->inspector().queue(ui::SelectResource{"normals"});
    ui->inspector().queue(ui::SetSetting{"prepass_mode", "depth"});
    ui->frame();
    const FrameResult& f = ui->inspector().frame();
    EXPECT_TRUE(ui->inspector().message().empty()) << ui->inspector().message();
    EXPECT_FALSE(f.inspected) << "no normals in depth mode";
    const std::vector<ResourceSummary> resources = f.resources;  // a copy
    for (const char* absent : {"normals", "roughness"})
        EXPECT_TRUE(std::none_of(resources.begin(), resources.end(), [&](const ResourceSummary& r) {
            return r.name == absent;
        })) << absent;
    EXPECT_TRUE(has_pass(f, "normals_from_depth"));
    for (const ResourceSummary& r : resources) {
        if (!r.is_image) continue;
        ui->inspector().queue(ui::SelectResource{r.name});
        ui->frame();
        const auto& shown = ui->inspector().frame().inspected;
        ASSERT_TRUE(shown) << r.name;
        EXPECT_EQ(shown->name, r.name);
    }
}

TEST_F(Inspector, SettingsChangeTheRendererAndFramesKeepComing) {
    auto ui = open("atrium");
    ui::Inspector& in = ui->inspector();
    const uint64_t before = in.frames_rendered();

    in.queue(ui::SetSetting{"msaa", "4"});
    ui->frame();
    EXPECT_EQ(in.settings().get("msaa"), "4");
    EXPECT_EQ(in.frame().msaa.samples, 4u);
    EXPECT_FALSE(in.frame().msaa.depth_resolve.empty());

    in.queue(ui::SetSetting{"prepass", "off"});
    ui->frame();
    EXPECT_FALSE(has_pass(in.frame(), "depth_prepass"));
    EXPECT_FALSE(has_pass(in.frame(), "gtao"));

    in.queue(ui::SetSetting{"prepass", "on"});
    in.queue(ui::SetSetting{"alpha_cutoff", "0.8"});
    ui->frame();
    EXPECT_TRUE(has_pass(in.frame(), "depth_prepass"));
    EXPECT_EQ(in.settings().get("alpha_cutoff"), "0.8");

    in.queue(ui::SetSetting{"msaa", "1"});
    ui->frame();
    EXPECT_EQ(in.frame().msaa.samples, 1u);
    EXPECT_EQ(in.frames_rendered(), before + 4);
    EXPECT_TRUE(in.message().empty()) << in.message();
}

TEST_F(Inspector, RaisingAlphaCutoffLowersWhatTheMaskedPipelineKeeps) {
    auto ui = open("foliage", settings_of({"count_discards=on"}));
    ui::Inspector& in = ui->inspector();
    in.queue(ui::SetSetting{"alpha_cutoff", "0.1"});
    ui->frame();
    ASSERT_TRUE(in.frame().find<DiscardCounts>());
    const uint64_t low = in.frame().find<DiscardCounts>()->discarded;
    in.queue(ui::SetSetting{"alpha_cutoff", "0.9"});
    ui->frame();
    EXPECT_GT(in.frame().find<DiscardCounts>()->discarded, low);
}

TEST_F(Inspector, ARefusedValueIsShownAndTheLastGoodSettingsStay) {
    auto ui = open("edges");
    ui::Inspector& in = ui->inspector();
    in.queue(ui::SetSetting{"msaa", "3"});  // the registry refuses it
    ui->frame();
    EXPECT_EQ(in.settings().get("msaa"), "1");
    EXPECT_NE(in.message().find("msaa"), std::string::npos) << in.message();
    // A count the registry allows but lavapipe does not (8): the frame falls back.
    in.queue(ui::SetSetting{"msaa", "8"});
    ui->frame();
    if (in.frame().msaa.samples != 8) {
        EXPECT_EQ(in.settings().get("msaa"), "1");
        EXPECT_NE(in.message().find("supports sample counts"), std::string::npos) << in.message();
    }
}

TEST_F(Inspector, ABadSceneFileKeepsTheCurrentScene) {
    auto ui = open("edges");
    ui::Inspector& in = ui->inspector();
    in.queue(ui::LoadScene{"/nonexistent/model.gltf"});
    ui->frame();
    EXPECT_EQ(in.scene().name, "edges");
    EXPECT_NE(in.message().find("no such file"), std::string::npos) << in.message();
    in.queue(ui::LoadScene{"overdraw"});
    ui->frame();
    EXPECT_EQ(in.scene().name, "overdraw");
    EXPECT_EQ(in.scene_summary().opaque, 8u);
}

TEST_F(Inspector, HoverReadoutOfTheDepthViewGivesTheLinearDepth) {
    // overdraw: layer 0, the nearest, is a view-filling quad at linear depth 2 (scene_facts.h).
    auto ui = open("overdraw");
    ui->inspector().queue(ui::SelectResource{"depth"});
    ui->frame();
    const uint32_t x = 37, y = 21;
    HeadlessInput hover;
    hover.mouse = screen_of(*ui, x, y);
    ui->frame(hover);
    const auto& readout = ui->inspector().viewer().hover;
    ASSERT_TRUE(readout);
    EXPECT_EQ(readout->x, x);
    EXPECT_EQ(readout->y, y);
    ASSERT_TRUE(readout->linear_depth);
    EXPECT_NEAR(*readout->linear_depth, 2.0f, 2e-3f);
    // The raw value is what reverse-Z stores for distance 2: n (f - d) / ((f - n) d).
    const scene::Camera& cam = ui->inspector().camera();
    const float expected = cam.znear * (cam.zfar - 2.0f) / ((cam.zfar - cam.znear) * 2.0f);
    EXPECT_NEAR(readout->raw[0], expected, 1e-6f);
    EXPECT_NE(readout->decoded_text.find("2.00"), std::string::npos) << readout->decoded_text;
}

// surface_id: hovering names the surface that won the pixel (overdraw: layer 0 everywhere).
TEST_F(Inspector, HoverReadoutOfSurfaceIdNamesTheSurface) {
    auto ui = open("overdraw");
    ui->inspector().queue(ui::SetSetting{"surface_id", "on"});
    ui->inspector().queue(ui::SelectResource{"surface_id"});
    ui->frame();
    HeadlessInput hover;
    hover.mouse = screen_of(*ui, 40, 30);
    ui->frame(hover);
    const auto& readout = ui->inspector().viewer().hover;
    ASSERT_TRUE(readout);
    const std::string& text = readout->decoded_text;
    EXPECT_NE(text.find("mesh layer_0, material layer_0, node layer_0, triangle "),
              std::string::npos)
        << text;
}

// zfight: hovering names what fights there; selecting a pair (the Depth panel's row) leaves
// only its pixels in the heat map, the others dimmed like the rest of the frame.
TEST_F(Inspector, ZfightViewNamesFightsAndShowsTheSelectedPair) {
    auto ui = open("zfight");
    ui->inspector().queue(ui::SetSetting{"zfight", "on"});
    ui->inspector().queue(ui::SelectResource{"zfight"});
    ui->frame();
    const FrameResult& f = ui->inspector().frame();
    ASSERT_TRUE(f.find<ZfightResult>());
    ASSERT_GE(f.find<ZfightResult>()->pairs.size(), 2u);
    auto first_hit = [&](uint32_t pair) {
        for (const ZfightHit& h : f.find<ZfightResult>()->hits)
            if (h.pair == pair) return h;
        ADD_FAILURE() << "no pixel for pair " << pair;
        return ZfightHit{};
    };
    const ZfightHit h0 = first_hit(0), h1 = first_hit(1);
    const uint32_t w = f.width;
    const auto text = ui->inspector().readout_at(h0.pixel % w, h0.pixel / w)->decoded_text;
    const ZfightPair& p0 = f.find<ZfightResult>()->pairs[0];
    EXPECT_NE(text.find(p0.a.node + " vs " + p0.b.node), std::string::npos) << text;
    auto colour = [&](uint32_t pixel) {
        const auto& v = ui->inspector().view();
        return std::vector<uint8_t>(v.rgba8.begin() + pixel * 4, v.rgba8.begin() + pixel * 4 + 3);
    };
    const auto before0 = colour(h0.pixel), before1 = colour(h1.pixel);
    ui->inspector().viewer().zfight_pair = 1;
    ui->frame();
    EXPECT_NE(colour(h0.pixel), before0) << "pair 0 is dimmed now";
    EXPECT_EQ(colour(h1.pixel), before1) << "pair 1 keeps its heat colour";
}

TEST_F(Inspector, ZoomedInTheReadoutNamesTheTexelDrawnUnderTheCursor) {
    auto ui = open("atrium");
    ui::ViewerState& v = ui->inspector().viewer();
    v.zoom = 4.0f;
    v.centre = {0.37f, 0.61f};  // a fractional origin: the blit's rounding shows
    ui->frame();
    const ds::view::DecodedView& view = ui->inspector().view();
    for (const glm::vec2 offset : {glm::vec2(0.13f, 0.21f), glm::vec2(0.5f, 0.5f),
                                   glm::vec2(0.91f, 0.77f), glm::vec2(0.02f, 0.97f)}) {
        HeadlessInput hover;
        hover.mouse = glm::vec2(std::floor(v.x + offset.x * v.w) + 0.5f,
                                std::floor(v.y + offset.y * v.h) + 0.5f);
        const std::vector<uint8_t> pixels = ui->frame(hover);
        const auto& readout = ui->inspector().viewer().hover;
        ASSERT_TRUE(readout);
        const size_t shown =
            (size_t(hover.mouse->y) * ui->size().width + size_t(hover.mouse->x)) * 4;
        const size_t texel = (size_t(readout->y) * view.width + readout->x) * 4;
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(pixels[shown + c], view.rgba8[texel + c])
                << "offset " << offset.x << "," << offset.y << " channel " << c;
    }
}

TEST_F(Inspector, SwitchingScenesDropsCutoffsOfMaterialsTheNewSceneLacks) {
    auto ui = open("foliage", settings_of({"material_alpha_cutoff=alpha_ramp=0.3"}));
    ui::Inspector& in = ui->inspector();
    EXPECT_EQ(in.settings().get("material_alpha_cutoff"), "alpha_ramp=0.3");
    in.queue(ui::LoadScene{"atrium"});
    ui->frame();
    EXPECT_EQ(in.scene().name, "atrium");
    EXPECT_EQ(in.settings().get("material_alpha_cutoff"), "");
    EXPECT_TRUE(in.message().empty()) << in.message();
    // Started on a scene without those materials (a saved setting): no error either.
    auto other = open("edges", settings_of({"material_alpha_cutoff=alpha_ramp=0.3"}));
    EXPECT_EQ(other->inspector().settings().get("material_alpha_cutoff"), "");
    EXPECT_TRUE(other->inspector().message().empty()) << other->inspector().message();
}

TEST_F(Inspector, ResetRebuildsABuiltInSceneBuiltFromSettings) {
    auto ui = open("overdraw");
    ui::Inspector& in = ui->inspector();
    in.queue(ui::SetSetting{"overdraw_layers", "3"});
    ui->frame();
    EXPECT_EQ(in.scene_summary().opaque, 3u);
    in.queue(ui::ResetSettings{});
    ui->frame();
    EXPECT_EQ(in.settings().get("overdraw_layers"), "8");
    EXPECT_EQ(in.scene_summary().opaque, 8u);
}

// The Advisor panel's "measure": both configurations through the inspector's renderer, camera
// and size; the overdraw comes from exact counts (every pixel covered by each layer), and the
// inspector's own settings and frames are as before.
TEST_F(Inspector, MeasureAdviceGivesTheOverdrawScenesLayers) {
    auto ui = open("overdraw", {}, {640, 360});
    ui::Inspector& in = ui->inspector();
    EXPECT_FALSE(in.advice());
    in.queue(ui::MeasureAdvice{});
    ui->frame();
    ASSERT_TRUE(in.advice()) << in.advice_error();
    EXPECT_DOUBLE_EQ(in.advice()->overdraw, 8.0);
    const VkExtent2D size = in.render_size();
    EXPECT_EQ(in.advice()->input.without.covered_pixels, uint64_t(size.width) * size.height);
    EXPECT_TRUE(in.advice()->keep);
    EXPECT_EQ(in.advice_label(),
              "overdraw at " + std::to_string(size.width) + "x" + std::to_string(size.height));
    EXPECT_EQ(in.settings().get("prepass"), "on");
    EXPECT_EQ(in.settings().get("count_fragments"), "off");
    EXPECT_TRUE(has_pass(in.frame(), "depth_prepass"));
    // The panel, opened, draws the result (an ImGui assertion would abort here).
    in.workspace().select("Advisor");
    ui->frame();
    const std::vector<uint8_t> pixels = ui->frame();
    EXPECT_EQ(in.workspace().open_tab(ui::Region::Right), "Advisor");
    if (const char* png = std::getenv("DS_ADVISOR_PNG"))
        capture::write_png_rgba8(png, 640, 360, pixels);

    in.queue(ui::SetSetting{"overdraw_layers", "3"});
    in.queue(ui::MeasureAdvice{});
    ui->frame();
    ASSERT_TRUE(in.advice()) << in.advice_error();
    EXPECT_DOUBLE_EQ(in.advice()->overdraw, 3.0);
    EXPECT_TRUE(in.advice_error().empty()) << in.advice_error();
    EXPECT_TRUE(in.message().empty()) << in.message();
}

TEST_F(Inspector, LeftDragOrbitsAndCtrlWheelZoomsTheImage) {
    auto ui = open("atrium");
    const ui::ViewerState& v = ui->inspector().viewer();
    const glm::vec2 centre{v.x + v.w * 0.5f, v.y + v.h * 0.5f};
    const glm::vec3 start = ui->inspector().camera().position;
    HeadlessInput press;
    press.mouse = centre;
    press.left = true;
    ui->frame(press);
    HeadlessInput drag = press;
    drag.mouse = centre + glm::vec2(60.0f, 0.0f);
    ui->frame(drag);
    const glm::vec3 moved = ui->inspector().camera().position;
    EXPECT_GT(glm::length(moved - start), 1e-3f);
    ui->frame({});  // release

    HeadlessInput zoom;
    zoom.mouse = centre;
    zoom.ctrl = true;
    zoom.wheel = 2.0f;
    ui->frame(zoom);
    EXPECT_NEAR(ui->inspector().viewer().zoom, 1.5625f, 1e-4f);
    EXPECT_EQ(glm::length(ui->inspector().camera().position - moved), 0.0f);  // not the camera
}

TEST(InspectorConfig, SettingsRoundTripThroughTheConfigFile) {
    const std::filesystem::path file =
        std::filesystem::path(::testing::TempDir()) / "ds_inspector_settings.ini";
    Settings s;
    s.set("msaa", "4");
    s.set("exposure", "2");
    ui::save_state(file, "foliage", s);
    const ui::SavedState loaded = ui::load_state(file);
    EXPECT_EQ(loaded.scene, "foliage");
    Settings back;
    for (const std::string& line : loaded.sets) back.apply(line);
    EXPECT_TRUE(back.diff(s).empty());
    EXPECT_TRUE(loaded.ignored.empty());
    {
        std::ofstream out(file, std::ios::app);
        out << "no_such_knob=1\nmsaa=banana\n";
    }
    EXPECT_EQ(ui::load_state(file).ignored.size(), 2u);
}

}  // namespace
}  // namespace ds::test

namespace ds::test {
namespace {

// Shader reload from the Shaders panel, on a renderer of its own reading a copy of shaders/:
// a compile error shows file:line and frames keep coming on the last good pipelines.
TEST(InspectorShaders, ACompileErrorIsShownAndTheLastGoodPipelinesKeepRunning) {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(::testing::TempDir()) / "ds_ui_shaders";
    fs::remove_all(root);
    fs::copy(DS_SHADER_DIR, root, fs::copy_options::recursive);
    ASSERT_EQ(setenv("DEPTHSCOPE_SHADER_DIR", root.c_str(), 1), 0);
    {
        RendererOptions options;
        options.validate = true;
        Renderer renderer(options);
        ui::HeadlessUi ui(renderer, Settings{}, scene::load_scene("edges", Settings{}), {640, 360});
        ui.frame();
        ui::Inspector& in = ui.inspector();
        const std::string good = ds::test::read_text(root / "tonemap.frag");
        { std::ofstream(root / "tonemap.frag", std::ios::app) << "\nthis is not glsl;\n"; }
        in.queue(ui::ReloadShaders{});
        const uint64_t before = in.frames_rendered();
        ui.frame();
        EXPECT_TRUE(in.shader_error());
        EXPECT_NE(in.shader_status().find("tonemap.frag:"), std::string::npos)
            << in.shader_status();
        ui.frame();
        EXPECT_EQ(in.frames_rendered(), before + 2);
        EXPECT_FALSE(in.frame().passes.empty());
        { std::ofstream(root / "tonemap.frag", std::ios::trunc) << good; }
        in.queue(ui::ReloadShaders{});
        ui.frame();
        EXPECT_FALSE(in.shader_error()) << in.shader_status();
        EXPECT_EQ(renderer.validation_message_count(), 0u);
    }
    unsetenv("DEPTHSCOPE_SHADER_DIR");
}

TEST(InspectorShaders, TheWatchSeesAnEditedFile) {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(::testing::TempDir()) / "ds_ui_watch";
    fs::remove_all(root);
    fs::create_directories(root / "common");
    std::ofstream(root / "common" / "a.glsl") << "// a\n";
    ui::ShaderWatch watch(root, std::chrono::milliseconds(0));
    EXPECT_FALSE(watch.changed());
    const auto later = fs::last_write_time(root / "common" / "a.glsl") + std::chrono::seconds(2);
    fs::last_write_time(root / "common" / "a.glsl", later);
    EXPECT_TRUE(watch.changed());
    EXPECT_FALSE(watch.changed());
    std::ofstream(root / "b.frag") << "// new\n";
    EXPECT_TRUE(watch.changed());
}

}  // namespace
}  // namespace ds::test
