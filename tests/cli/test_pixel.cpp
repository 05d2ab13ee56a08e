// depthscope pixel, the real executable: the overdraw scene's layers with the prepass off and
// on, a foliage cut-out (the pixel derived from the frame's own discard count image, rendered
// in-process with the same scene, size and settings), and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "renderer/renderer.h"
#include "renderer/scene/builtin/scene_facts.h"
#include "renderer/scene/loader.h"
#include "tests/support/run_process.h"

using ds::test::run_depthscope;
namespace facts = ds::scene::builtin::facts;

namespace {

constexpr int kLayers = 8;  // overdraw_layers' default

nlohmann::json pixel_json(const std::string& name, const std::string& args) {
    const auto path = ds::test::fresh_dir(name) / "pixel.json";
    const auto r = run_depthscope("pixel --validate " + args + " --json " + path.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("fragments"), std::string::npos) << r.out;
    return nlohmann::json::parse(ds::test::read_file(path));
}

nlohmann::json of_pass(const nlohmann::json& history, const std::string& pass) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& f : history["fragments"])
        if (f["pass"] == pass) out.push_back(f);
    return out;
}

constexpr const char* kOverdraw = "--scene overdraw --size 320x180 --at 201,77";

}  // namespace

TEST(Pixel, OverdrawWithoutPrepassListsEveryLayerAndEndsWithTheFrontOne) {
    const auto json = pixel_json("pixel_off", std::string(kOverdraw) + " --set prepass=off");
    EXPECT_EQ(json["pixel"], nlohmann::json({201, 77}));
    const auto forward = of_pass(json, "forward");
    ASSERT_EQ(forward.size(), size_t(kLayers)) << json.dump(1);
    EXPECT_EQ(json["fragments"].size(), size_t(kLayers));
    for (int i = 0; i < kLayers; ++i) {
        const auto& f = forward[size_t(i)];
        const int layer = kLayers - 1 - i;  // authored farthest first
        EXPECT_EQ(f["material"], "layer_" + std::to_string(layer));
        EXPECT_NEAR(f["linear_depth"].get<double>(), facts::overdraw_layer_depth(layer), 1e-3);
        EXPECT_EQ(f["depth_test"]["passed"], true);
        EXPECT_EQ(f["shaded"], true);
        EXPECT_TRUE(f["alpha_test"].is_null());
        EXPECT_TRUE(f["blended"].is_null());
        EXPECT_EQ(f["color"].size(), 4u);
    }
    // The final colour is the front layer's: what the pixel shows with that layer alone. Both
    // without shadows: the shadow map is fitted to the scene's bounds, which the layer count
    // changes, so its filtered lookup may differ in the last bit (it does on an NVIDIA H200).
    const auto lit =
        pixel_json("pixel_lit", std::string(kOverdraw) + " --set prepass=off --set shadows=off");
    const auto alone = pixel_json("pixel_one", std::string(kOverdraw) +
                                                   " --set prepass=off --set shadows=off "
                                                   "--set overdraw_layers=1");
    ASSERT_EQ(alone["fragments"].size(), 1u);
    EXPECT_EQ(alone["fragments"][0]["material"], "layer_0");
    EXPECT_EQ(lit["final_color"], alone["final_color"]);
    EXPECT_EQ(of_pass(lit, "forward").back()["color"], alone["fragments"][0]["color"]);
}

TEST(Pixel, OverdrawWithPrepassPassesOnceInEachPass) {
    const auto json = pixel_json("pixel_on", std::string(kOverdraw) + " --set prepass_sort=on");
    const auto prepass = of_pass(json, "depth_prepass");
    ASSERT_EQ(prepass.size(), size_t(kLayers)) << json.dump(1);
    for (int i = 0; i < kLayers; ++i) {
        EXPECT_EQ(prepass[size_t(i)]["material"], "layer_" + std::to_string(i));  // front first
        EXPECT_EQ(prepass[size_t(i)]["depth_test"]["passed"], i == 0);
    }
    int passing = 0;
    for (const auto& f : of_pass(json, "forward")) {
        if (f["depth_test"]["passed"] != true) continue;
        ++passing;
        EXPECT_EQ(f["material"], "layer_0");
        EXPECT_EQ(f["shaded"], true);
    }
    EXPECT_EQ(passing, 1);
}

// The cut-out pixel: where the frame's prepass discard count image (count_fragments=on, read
// in-process with the same scene, size and settings) is not zero.
TEST(Pixel, FoliageCutOutIsADiscardedMaskedPrepassFragment) {
    constexpr uint32_t kW = 160, kH = 90;
    ds::Settings settings;
    settings.apply("count_fragments=on");
    std::optional<std::pair<uint32_t, uint32_t>> cut;
    uint32_t discarded = 0;
    {
        ds::Renderer renderer(ds::RendererOptions{});
        const ds::scene::Scene scene = ds::scene::load_scene("foliage", settings);
        renderer.set_scene(scene);
        const ds::FrameResult f = renderer.render(scene.camera, settings,
                                                  {.width = kW,
                                                   .height = kH,
                                                   .read_back = ds::ReadBack::No,
                                                   .inspect = {{"prepass_discarded"}}});
        ASSERT_TRUE(f.inspected);
        for (uint32_t i = 0; i < kW * kH && !cut; ++i) {
            if (f.inspected->texels[size_t(i) * 4] > 0) {
                cut = {i % kW, i / kW};
                discarded = uint32_t(f.inspected->texels[size_t(i) * 4]);
            }
        }
    }
    ASSERT_TRUE(cut);
    const std::string at = std::to_string(cut->first) + "," + std::to_string(cut->second);
    const auto json = pixel_json("pixel_foliage", "--scene foliage --size 160x90 --at " + at);
    uint32_t cut_away = 0;
    for (const auto& f : of_pass(json, "depth_prepass")) {
        if (f["alpha_test"].is_null() || f["alpha_test"]["passed"] == true) continue;
        ++cut_away;
        EXPECT_LT(f["alpha_test"]["alpha"].get<double>(), f["alpha_test"]["cutoff"].get<double>());
        EXPECT_EQ(f["shaded"], true);  // the masked pipeline's discard costs it early-Z
        EXPECT_TRUE(f["color"].is_null());
    }
    EXPECT_EQ(cut_away, discarded) << json.dump(1);
}

TEST(Pixel, BadInputIsOneLineAndNonzero) {
    for (const char* args :
         {"--at 12", "--at 1,2,3", "--at -1,5", "--at x,y", "--at 320,0 --size 320x180",
          "--at 0,180 --size 320x180", "--size 0x5 --at 0,0"}) {
        const auto r = run_depthscope(std::string("pixel --scene overdraw ") + args);
        EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
        EXPECT_EQ(ds::test::count_lines(r.err), 1u) << args << ": " << r.err;
        EXPECT_EQ(r.err.rfind("depthscope: error: ", 0), 0u) << r.err;
    }
    const auto missing = run_depthscope("pixel --scene overdraw");
    EXPECT_EQ(missing.exit_code, 2) << missing.err;
    // An unwritable --json: one line, nonzero, no file.
    const auto dir = ds::test::fresh_dir("pixel_bad_json");
    const auto path = dir / "no" / "such" / "pixel.json";
    const auto r =
        run_depthscope("pixel --scene overdraw --size 64x36 --at 1,1 --json " + path.string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_EQ(ds::test::count_lines(r.err), 1u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(path));
}
