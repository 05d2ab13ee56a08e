// frame_report() and passes_json(): which fields report.json has, and when the optional ones
// appear (only when measured, so that "not counted" never reads as zero).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "capture/report.h"
#include "renderer/passes/depth_prepass.h"
#include "renderer/passes/draw_counts.h"
#include "renderer/passes/hiz.h"
#include "renderer/passes/zfight.h"

namespace ds::capture {
namespace {

std::set<std::string> keys(const nlohmann::json& object) {
    std::set<std::string> out;
    for (const auto& item : object.items()) out.insert(item.key());
    return out;
}

FrameResult two_pass_frame() {
    FrameResult frame;
    frame.width = 32;
    frame.height = 16;
    frame.gpu_ms = 2.5;
    frame.passes.resize(2);
    frame.passes[0].name = "depth_prepass";
    frame.passes[0].vertex_shader_invocations = 30;
    frame.passes[1].name = "forward";
    frame.passes[1].shaded_fragments = 512;
    frame.skipped = {"gtao: skipped (prepass off)"};
    return frame;
}

nlohmann::json report_of(const FrameResult& frame, const Settings& settings = {}) {
    scene::Scene scene;
    scene.name = "made-up";
    return frame_report({.device = {.name = "gpu",
                                    .driver = "driver 1",
                                    .api_version = "1.3.0",
                                    .fragment_statistic = "counts every other fragment",
                                    .msaa_counts = {1, 4}},
                         .scene = scene,
                         .settings = settings,
                         .frame = frame,
                         .validation_messages = 2});
}

TEST(Report, HasEveryFieldOfAFrameAndOnlyTheMeasuredOptionalOnes) {
    const nlohmann::json report = report_of(two_pass_frame());
    EXPECT_EQ(keys(report),
              (std::set<std::string>{"tool", "version", "device", "scene", "size", "settings",
                                     "frame", "validation_messages", "passes", "counters",
                                     "skipped", "msaa", "decals", "tiler"}));
    EXPECT_EQ(report["tiler"]["ran"], "dynamic");  // always there: why there is no render pass
    EXPECT_EQ(report["decals"], (nlohmann::json{{"overlays", nlohmann::json::array()},
                                                {"buried", nlohmann::json::array()},
                                                {"decals_pass", false}}));
    EXPECT_EQ(report["device"]["driver"], "driver 1");
    // The statistic is labelled with what it means on this device.
    EXPECT_NE(report["counters"]["stats"].get<std::string>().find("counts every other fragment"),
              std::string::npos);
    EXPECT_EQ(report["size"]["width"], 32);
    EXPECT_EQ(report["frame"]["gpu_ms"], 2.5);
    EXPECT_EQ(report["validation_messages"], 2);
    EXPECT_EQ(report["skipped"].size(), 1u);
    EXPECT_EQ(report["msaa"], (nlohmann::json{{"samples", 1}}));
    EXPECT_TRUE(report["settings"].is_object());
    EXPECT_EQ(report["settings"].size(), Settings{}.values().size());
}

// Each classified overlay names itself and its base (mesh, material, node) and its alpha mode;
// decals_pass says whether this frame drew them in the decals pass.
TEST(Report, DecalsNameOverlayAndBase) {
    scene::Scene scene;
    scene.materials.resize(2);
    scene.materials[0].name = "plaster";
    scene.materials[1].name = "poster";
    scene.materials[1].alpha_mode = scene::AlphaMode::Mask;
    scene.meshes.resize(2);
    scene.meshes[0].name = "wall_mesh";
    scene.meshes[1].name = "poster_mesh";
    scene.meshes[1].material = 1;
    scene.instances.resize(2);
    scene.instances[0].node = "wall";
    scene.instances[1] = {.mesh = 1, .world = glm::mat4(1.0f), .node = "poster"};
    scene.decals = {{.instance = 1, .base = 0}};
    scene.buried = {{.instance = 0, .base = 1, .gap = 0.002}};
    FrameResult frame = two_pass_frame();
    frame.passes.push_back({});
    frame.passes.back().name = "decals";
    const nlohmann::json report = frame_report(
        {.device = {}, .scene = scene, .settings = {}, .frame = frame, .validation_messages = 0});
    const nlohmann::json expected = {
        {"overlays",
         {{{"overlay", {{"mesh", "poster_mesh"}, {"material", "poster"}, {"node", "poster"}}},
           {"base", {{"mesh", "wall_mesh"}, {"material", "plaster"}, {"node", "wall"}}},
           {"alpha_mode", "mask"}}}},
        {"buried",
         {{{"overlay", {{"mesh", "wall_mesh"}, {"material", "plaster"}, {"node", "wall"}}},
           {"base", {{"mesh", "poster_mesh"}, {"material", "poster"}, {"node", "poster"}}},
           {"gap", 0.002}}}},
        {"decals_pass", true}};
    EXPECT_EQ(report["decals"], expected);
}

TEST(Report, PassesKeepOrderStatsAndTheExactCountOnlyWhereCounted) {
    const nlohmann::json passes = report_of(two_pass_frame())["passes"];
    ASSERT_EQ(passes.size(), 2u);
    EXPECT_EQ(passes[0]["name"], "depth_prepass");
    EXPECT_EQ(keys(passes[0]), (std::set<std::string>{"name", "kind", "gpu_ms", "stats"}));
    EXPECT_EQ(passes[0]["kind"], "frame");
    EXPECT_EQ(passes[0]["stats"]["vertex_shader_invocations"], 30);
    // Counted without quads: the device has no quad subgroup operations, and the report says so.
    EXPECT_EQ(keys(passes[1]), (std::set<std::string>{"name", "kind", "gpu_ms", "stats",
                                                      "shaded_fragments", "quad_overdraw"}));
    EXPECT_EQ(passes[1]["shaded_fragments"], 512);
    EXPECT_EQ(passes[1]["quad_overdraw"], "unsupported on this device");
}

// The three exact counts per pass, and quads as quads, lanes and lanes per shaded fragment.
TEST(Report, CountedPassesGiveRasterizedShadedDiscardedAndQuads) {
    FrameResult frame = two_pass_frame();
    PassResult& forward = frame.passes[1];
    forward.rasterized_fragments = 2048;
    forward.discarded_fragments = 12;
    forward.quads = 160;
    const nlohmann::json pass = report_of(frame)["passes"][1];
    EXPECT_EQ(pass["rasterized_fragments"], 2048);
    EXPECT_EQ(pass["shaded_fragments"], 512);
    EXPECT_EQ(pass["discarded_fragments"], 12);
    EXPECT_EQ(pass["quad_overdraw"],
              (nlohmann::json{{"quads", 160}, {"lanes", 640}, {"lanes_per_shaded", 1.25}}));
}

// A geometry pass lists its pipelines (name, early-Z verdict, draws, whether it has a fragment
// stage) in bind order; a pass that bound none has no "pipelines" key.
TEST(Report, PassesListTheirPipelinesOnlyWhereTheyDrew) {
    FrameResult frame = two_pass_frame();
    frame.passes[0].pipelines = {{"depth_prepass opaque z-only", "guaranteed", 12, false},
                                 {"depth_prepass mask", "lost: discard", 3}};
    const nlohmann::json passes = report_of(frame)["passes"];
    EXPECT_EQ(passes[0]["pipelines"], (nlohmann::json{{{"name", "depth_prepass opaque z-only"},
                                                       {"early_z", "guaranteed"},
                                                       {"draws", 12},
                                                       {"fragment_stage", false}},
                                                      {{"name", "depth_prepass mask"},
                                                       {"early_z", "lost: discard"},
                                                       {"draws", 3},
                                                       {"fragment_stage", true}}}));
    EXPECT_FALSE(passes[1].contains("pipelines"));
}

TEST(Report, OptionalCountsAppearWhenMeasured) {
    FrameResult frame = two_pass_frame();
    frame.covered_pixels = 100;
    frame.slots.put(DiscardCounts{.invoked = 9, .discarded = 4}, &passes::discards_report);
    frame.msaa.samples = 4;
    frame.msaa.depth_resolve = "shader";
    frame.msaa.edge_pixels = 7;
    const nlohmann::json report = report_of(frame);
    EXPECT_EQ(report["coverage"], (nlohmann::json{{"covered_pixels", 100}}));
    EXPECT_EQ(report["masked_discards"], (nlohmann::json{{"invoked", 9}, {"discarded", 4}}));
    EXPECT_EQ(report["msaa"],
              (nlohmann::json{{"samples", 4}, {"depth_resolve", "shader"}, {"edge_pixels", 7}}));
}

TEST(Report, ZfightNamesBothSurfacesOfEveryPair) {
    FrameResult frame = two_pass_frame();
    const nlohmann::json none = report_of(frame);
    EXPECT_FALSE(none.contains("zfight")) << "only with zfight=on";
    ZfightResult& zfight = frame.slots.put(ZfightResult{}, &passes::zfight_report);
    zfight.steps = 4;
    zfight.pixels = 12;
    zfight.pairs = {{{"quad", "red", "a"}, {"quad", "blue", "b"}, 12, 1}};
    const nlohmann::json z = report_of(frame)["zfight"];
    EXPECT_EQ(z["steps"], 4);
    EXPECT_EQ(z["pixels"], 12);
    ASSERT_EQ(z["pairs"].size(), 1u);
    EXPECT_EQ(z["pairs"][0]["a"],
              (nlohmann::json{{"mesh", "quad"}, {"material", "red"}, {"node", "a"}}));
    EXPECT_EQ(z["pairs"][0]["b"]["material"], "blue");
    EXPECT_EQ(z["pairs"][0]["pixels"], 12);
    EXPECT_EQ(z["pairs"][0]["min_steps"], 1);
    EXPECT_FALSE(z.contains("dropped_records"));
}

// The scene depth's facts: the format's name, the planes as written (0.1f is 0.1), the
// convention.
TEST(Report, DepthSaysTheFormatAndThePlanes) {
    FrameResult frame = two_pass_frame();
    frame.depth = DepthResult{
        .format = VK_FORMAT_D24_UNORM_S8_UINT, .znear = 0.1f, .zfar = 250.0f, .reverse_z = false};
    EXPECT_EQ(
        report_of(frame)["depth"],
        (nlohmann::json{
            {"format", "D24_UNORM_S8_UINT"}, {"znear", 0.1}, {"zfar", 250}, {"reverse_z", false}}));
}

TEST(Report, PassesJsonMergesWhatTheCallerMeasured) {
    FrameResult frame = two_pass_frame();
    frame.passes[1].role = graph::PassRole::ReadBack;
    const nlohmann::json passes = passes_json(frame.passes, [](size_t i) {
        return nlohmann::json{{"run", i}};
    });
    EXPECT_EQ(passes, (nlohmann::json{{{"name", "depth_prepass"}, {"kind", "frame"}, {"run", 0}},
                                      {{"name", "forward"}, {"kind", "readback"}, {"run", 1}}}));
}

// count_draws: one entry per draw group with its names, instance range, counts per pass and the
// occluded flag; a count that was not measured is null, never 0; draws_info says where
// samples_passed came from and why visible pixels are missing.
TEST(Report, DrawsListEveryGroupWithNullsWhereNotMeasured) {
    FrameResult frame = two_pass_frame();
    DrawsResult& counted = frame.slots.put(DrawsResult{}, &passes::draws_report);
    counted.samples_pass = "forward";
    counted.visible_note = "prepass=off: no surface_id";
    DrawReport wall;
    wall.name = {"wall_mesh", "plaster", "wall"};
    wall.instances = 3;
    wall.alpha_mode = "opaque";
    wall.samples_passed = 0;
    wall.shaded_fragments = {{"forward", 7}, {"transparent", 0}};
    wall.occluded = true;
    DrawReport glass;
    glass.group = 1;
    glass.name = {"glass_mesh", "glass", "pane"};
    glass.first_instance = 3;
    glass.instances = 1;
    glass.alpha_mode = "blend";
    glass.shaded_fragments = {{"forward", 0}, {"transparent", 40}};
    counted.draws = {wall, glass};
    const nlohmann::json report = report_of(frame);
    ASSERT_TRUE(report.contains("draws"));
    const nlohmann::json& draws = report["draws"];
    ASSERT_EQ(draws.size(), 2u);
    EXPECT_EQ(draws[0], (nlohmann::json{{"mesh", "wall_mesh"},
                                        {"material", "plaster"},
                                        {"node", "wall"},
                                        {"group", 0},
                                        {"instances", {0, 3}},
                                        {"alpha_mode", "opaque"},
                                        {"visible_pixels", nullptr},
                                        {"samples_passed", 0},
                                        {"shaded_fragments", {{"forward", 7}, {"transparent", 0}}},
                                        {"wasted_fragments", nlohmann::json::object()},
                                        {"occluded", true}}));
    EXPECT_TRUE(draws[1]["samples_passed"].is_null());
    EXPECT_EQ(draws[1]["shaded_fragments"]["transparent"], 40);
    EXPECT_EQ(draws[1]["occluded"], false);
    EXPECT_EQ(report["draws_info"]["samples_passed_from"], "forward");
    EXPECT_EQ(report["draws_info"]["visible_pixels"], "prepass=off: no surface_id");
    EXPECT_FALSE(report_of(two_pass_frame()).contains("draws"));
}

// hiz=on: the pyramid's levels and the verdicts' tally; with count_draws each draw carries its
// verdict beside samples_passed, and an unsafe one says so. Without count_draws the counts are
// null (not measured), never 0; hiz off leaves both out.
TEST(Report, HizGivesLevelsAndEachDrawsVerdictBesideSamplesPassed) {
    FrameResult frame = two_pass_frame();
    HizResult& hiz = frame.slots.put(HizResult{}, &passes::hiz_report);
    hiz.levels = {{5, 3}, {2, 1}, {1, 1}};
    hiz.source = "depth";
    const nlohmann::json pyramid_only = report_of(frame);
    EXPECT_EQ(pyramid_only["hiz"], (nlohmann::json{{"levels", {{5, 3}, {2, 1}, {1, 1}}},
                                                   {"source", "depth"},
                                                   {"samples", 1},
                                                   {"farthest", "min (reverse-Z)"},
                                                   {"unsafe_draws", nullptr},
                                                   {"unsafe_visible_draws", nullptr}}));
    EXPECT_FALSE(report_of(two_pass_frame()).contains("hiz"));
    DrawReport back, front;
    back.samples_passed = 12;
    back.hiz = HizVerdict::Occluded;
    back.hiz_occluded_instances = 1;
    back.hiz_unsafe = true;
    front.group = 1;
    front.samples_passed = 40;
    front.hiz = HizVerdict::Visible;
    frame.slots.put(DrawsResult{.draws = {back, front}}, &passes::draws_report);
    hiz.groups = {HizVerdict::Occluded, HizVerdict::Visible};
    hiz.unsafe = 1;
    hiz.unsafe_visible = 0;
    const nlohmann::json report = report_of(frame);
    EXPECT_EQ(report["hiz"]["draws"],
              (nlohmann::json{{"visible", 1}, {"occluded", 1}, {"outside", 0}}));
    EXPECT_EQ(report["hiz"]["unsafe_draws"], 1);
    EXPECT_EQ(report["hiz"]["unsafe_visible_draws"], 0);
    EXPECT_EQ(report["draws"][0]["hiz"], "occluded");
    EXPECT_EQ(report["draws"][0]["hiz_occluded_instances"], 1);
    EXPECT_EQ(report["draws"][0]["hiz_unsafe"], true);
    EXPECT_EQ(report["draws"][0]["samples_passed"], 12);
    EXPECT_EQ(report["draws"][1]["hiz"], "visible");
    EXPECT_EQ(report["draws"][1]["hiz_unsafe"], false);
}

}  // namespace
}  // namespace ds::capture
