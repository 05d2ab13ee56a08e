// depthscope lint through the real executable: the built-in scenes (zfight's pairs exactly,
// with the fight distances view/precision.h's model gives; decals' overlays as DECAL infos;
// overdraw's layers; atrium clean), a hand-made scene of every kind of pair, the report's
// glTF-Validator shape with pointers that resolve in the file, --config, bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/view/precision.h"
#include "tests/cli/lint_scene.h"
#include "tests/support/run_process.h"

namespace {

using ds::test::run_depthscope;
using nlohmann::json;

struct Lint {
    int exit_code = -1;
    std::string out, err;
    json report;
};

Lint run_lint(const std::string& name, const std::string& args) {
    const auto path = ds::test::fresh_dir("lint_" + name) / "lint.json";
    const auto r = run_depthscope("lint " + args + " --validate --json " + path.string(), 300);
    Lint l{r.exit_code, r.out, r.err, json::object()};
    if (std::filesystem::exists(path)) l.report = json::parse(ds::test::read_file(path));
    return l;
}

std::vector<json> with_code(const json& report, const std::string& code) {
    std::vector<json> out;
    for (const json& m : report["issues"]["messages"])
        if (m["code"] == code) out.push_back(m);
    return out;
}

std::set<std::string> node_pair(const json& m) {
    return {m["surfaces"][0]["node"].get<std::string>(),
            m["surfaces"][1]["node"].get<std::string>()};
}

ds::view::DepthConfig format_named(const std::string& name, double n, double f) {
    if (name == "d16") return {16, false, n, f};
    if (name == "d24") return {24, false, n, f};
    return {32, name == "d32f reverse-Z", n, f};
}

// The report's distance for `format` is where the model's step first reaches the gap: the
// step there is at least the gap, and a little nearer it is below.
void expect_fight_distance(const json& m, const json& depth, const std::string& format) {
    const double gap = m["values"]["gap"], d = m["values"][format];
    const ds::view::DepthConfig c = format_named(format, depth["znear"], depth["zfar"]);
    EXPECT_GE(ds::view::step_at(c, d * (1 + 1e-9)), gap) << format << " " << m["message"];
    EXPECT_LT(ds::view::step_at(c, d * (1 - 1e-6)), gap) << format << " " << m["message"];
}

TEST(Lint, BuiltInScenesFindExactlyTheirPairsDecalsAndOverdraw) {
    const Lint l = run_lint("builtins", "zfight decals overdraw atrium");
    ASSERT_EQ(l.report.size(), 4u) << l.err << l.out;
    EXPECT_EQ(l.exit_code, 1) << "zfight's coplanar pairs are errors";
    const json &zfight = l.report[0], &decals = l.report[1], &overdraw = l.report[2],
               &atrium = l.report[3];
    // zfight: 6 slots, each an exactly coplanar pair and a near pair, nothing else. The near
    // pairs' back quads are pushed along the view ray, not the normal: seen head-on, slot 3's
    // lies beside its front quad (they overlap only from the scene's camera; surface_pairs.h),
    // so 5 of the 6 are near pairs, each between its own slot's quads.
    const auto coplanar = with_code(zfight, "COPLANAR_OVERLAP");
    const auto near = with_code(zfight, "NEAR_COPLANAR_FIGHT");
    ASSERT_EQ(coplanar.size(), 6u) << zfight.dump(1);
    ASSERT_EQ(near.size(), 5u) << zfight.dump(1);
    std::set<std::string> near_slots;
    for (const json& m : near) {
        const std::string a = m["surfaces"][0]["node"], b = m["surfaces"][1]["node"];
        EXPECT_EQ(a.substr(a.rfind('_')), b.substr(b.rfind('_'))) << a << " " << b;
        near_slots.insert(a.substr(a.rfind('_')));
    }
    EXPECT_EQ(near_slots, (std::set<std::string>{"_0", "_1", "_2", "_4", "_5"}));
    for (const json& m : coplanar) {
        EXPECT_EQ(m["severity"], 0);
        EXPECT_EQ(m["surfaces"][0]["material"].get<std::string>().substr(0, 9), "coplanar_");
        EXPECT_EQ(m["surfaces"][1]["material"].get<std::string>().substr(0, 9), "coplanar_");
        EXPECT_NE(m["surfaces"][0]["material"], m["surfaces"][1]["material"]);
    }
    for (const json& m : near) {
        EXPECT_EQ(m["surfaces"][0]["material"].get<std::string>().substr(0, 5), "near_");
        EXPECT_EQ(m["surfaces"][1]["material"].get<std::string>().substr(0, 5), "near_");
        for (const char* f : {"d32f reverse-Z", "d32f forward-Z", "d24", "d16"})
            if (m["values"].contains(f)) expect_fight_distance(m, zfight["depth"], f);
        EXPECT_TRUE(m["values"].contains("d16")) << "every near pair fights in d16";
        // A warning exactly when the chosen format (d32f reverse-Z) has a distance.
        EXPECT_EQ(m["severity"] == 1, m["values"].contains("d32f reverse-Z")) << m["message"];
    }
    EXPECT_EQ(zfight["issues"]["numErrors"], 6);
    // decals: every overlay is a DECAL info with its base; no error.
    EXPECT_EQ(decals["issues"]["numErrors"], 0) << decals.dump(1);
    EXPECT_EQ(with_code(decals, "DECAL").size(), 5u);
    // overdraw: its layers cover the whole view, each pixel overdraw_layers (8) times.
    const auto od = with_code(overdraw, "OVERDRAW");
    ASSERT_FALSE(od.empty()) << overdraw.dump(1);
    EXPECT_EQ(od[0]["severity"], 1);
    EXPECT_DOUBLE_EQ(od[0]["magnitude"]["value"].get<double>(), 8.0);
    EXPECT_EQ(atrium["issues"]["numErrors"], 0) << atrium.dump(1);
}

// Every kind of pair in a scene lint has never seen: nodes placing unit squares (lint_scene.h).
std::filesystem::path write_pairs_scene(const std::filesystem::path& dir) {
    using ds::test::LintNode;
    const std::vector<LintNode> nodes = {
        {"floor_a", ds::test::kSquare, 0, {0, 0, 0}, {0, 0, 0, 1}, 2.0},
        {"floor_b", ds::test::kSquareOtherDiagonal, 0, {0.5, 0, 0}, {0, 0, 0, 1}, 2.0},
        {"dup_a", ds::test::kSquare, 0, {10, 0, 0}},
        {"dup_b", ds::test::kSquare, 0, {10, 0, 0}},
        {"near_back", ds::test::kSquare, 0, {20, 0, 0}},
        {"near_front", ds::test::kSquare, 0, {20, 0, 0.002}},
        {"sliver", ds::test::kSliver, 0, {30, 0, 0}},
        {"blend_solid", ds::test::kSquare, 1, {40, 0, 0}},
        {"opaque_half", ds::test::kSquare, 2, {50, 0, 0}},
        {"tile_a", ds::test::kSquare, 0, {70, 0, 0}},
        {"tile_b", ds::test::kSquare, 0, {71, 0, 0}},
        // Facing each other (one turned over about Y): single-sided, they do not pair.
        {"back_to_back", ds::test::kSquare, 0, {80, 0, 0}, {0, 1, 0, 0}},
        {"front_to_front", ds::test::kSquare, 0, {80, 0, 0}},
    };
    const std::vector<ds::test::LintMaterial> materials = {
        {"grey"}, {"blend_solid", "BLEND", 1.0}, {"opaque_half", "OPAQUE", 0.5}};
    return ds::test::write_lint_scene(dir, "pairs", nodes, materials);
}

TEST(Lint, HandMadePairsDuplicatesNearPairsAlphaModesAndSlivers) {
    const auto dir = ds::test::fresh_dir("lint_pairs_scene");
    const auto gltf = write_pairs_scene(dir);
    const Lint l = run_lint("pairs", gltf.string() + " --set depth_format=d24");
    ASSERT_TRUE(l.report.contains("issues")) << l.err << l.out;
    const json& r = l.report;
    const auto coplanar = with_code(r, "COPLANAR_OVERLAP");
    ASSERT_EQ(coplanar.size(), 1u) << r.dump(1);
    EXPECT_EQ(node_pair(coplanar[0]), (std::set<std::string>{"floor_a", "floor_b"}));
    EXPECT_NEAR(coplanar[0]["magnitude"]["value"].get<double>(), 1.5 * 2.0, 1e-9);
    const auto dup = with_code(r, "DUPLICATE_INSTANCE");
    ASSERT_EQ(dup.size(), 1u) << r.dump(1);
    EXPECT_EQ(node_pair(dup[0]), (std::set<std::string>{"dup_a", "dup_b"}));
    const auto near = with_code(r, "NEAR_COPLANAR_FIGHT");
    ASSERT_EQ(near.size(), 1u) << r.dump(1);
    EXPECT_EQ(node_pair(near[0]), (std::set<std::string>{"near_back", "near_front"}));
    EXPECT_NEAR(near[0]["values"]["gap"].get<double>(), 0.002, 1e-6);
    for (const char* f : {"d32f reverse-Z", "d32f forward-Z", "d24", "d16"})
        if (near[0]["values"].contains(f)) expect_fight_distance(near[0], r["depth"], f);
    EXPECT_EQ(near[0]["severity"] == 1, near[0]["values"].contains("d24"));
    const auto degenerate = with_code(r, "DEGENERATE_TRIANGLE");
    ASSERT_EQ(degenerate.size(), 1u) << r.dump(1);
    EXPECT_EQ(degenerate[0]["magnitude"]["value"], 1.0);
    const auto alpha = with_code(r, "ALPHA_MODE");
    ASSERT_EQ(alpha.size(), 2u) << r.dump(1);
    std::set<std::string> pointers;
    for (const json& m : alpha) pointers.insert(m["pointer"].get<std::string>());
    EXPECT_EQ(pointers, (std::set<std::string>{"/materials/1", "/materials/2"}));
    EXPECT_EQ(r["issues"]["numErrors"], 2);
    EXPECT_EQ(l.exit_code, 1);
}

// glTF-Validator's report: its keys and types, severities 0..3 counted per level, and every
// pointer a JSON pointer that resolves in the linted file.
TEST(Lint, ReportReadsBackInGltfValidatorsShapeWithPointersIntoTheFile) {
    const auto dir = ds::test::fresh_dir("lint_shape_scene");
    const auto gltf = write_pairs_scene(dir);
    const Lint l = run_lint("shape", gltf.string());
    const json& r = l.report;
    ASSERT_TRUE(r.is_object()) << l.err;
    for (const char* key : {"uri", "mimeType", "validatorVersion"})
        EXPECT_TRUE(r[key].is_string()) << key;
    EXPECT_EQ(r["mimeType"], "model/gltf+json");
    const json& issues = r["issues"];
    for (const char* key : {"numErrors", "numWarnings", "numInfos", "numHints"})
        EXPECT_TRUE(issues[key].is_number_unsigned()) << key;
    EXPECT_TRUE(issues["truncated"].is_boolean());
    const json file = json::parse(ds::test::read_file(gltf));
    int per_level[4] = {0, 0, 0, 0};
    for (const json& m : issues["messages"]) {
        ASSERT_TRUE(m["code"].is_string() && m["message"].is_string() && m["pointer"].is_string());
        const int s = m["severity"].get<int>();
        ASSERT_TRUE(s >= 0 && s <= 3);
        ++per_level[s];
        const std::string pointer = m["pointer"];
        if (!pointer.empty()) {
            EXPECT_TRUE(file.contains(json::json_pointer(pointer))) << pointer << " " << m["code"];
        }
    }
    EXPECT_EQ(issues["numErrors"], per_level[0]);
    EXPECT_EQ(issues["numWarnings"], per_level[1]);
    EXPECT_EQ(issues["numInfos"], per_level[2]);
    EXPECT_EQ(issues["numHints"], per_level[3]);
    EXPECT_GT(per_level[0] + per_level[1] + per_level[2], 0);
}

TEST(Lint, ConfigIgnoresOverridesTruncatesAndSetsTheExitCode) {
    const auto dir = ds::test::fresh_dir("lint_config_scene");
    const auto gltf = write_pairs_scene(dir);
    const auto config = [&](const std::string& name, const json& j) {
        std::ofstream(dir / name) << j.dump();
        return " --config " + (dir / name).string();
    };
    const Lint plain = run_lint("config_plain", gltf.string());
    EXPECT_EQ(plain.exit_code, 1);
    EXPECT_FALSE(with_code(plain.report, "COPLANAR_OVERLAP").empty());
    const Lint ignored =
        run_lint("config_ignore",
                 gltf.string() + config("ignore.json",
                                        {{"ignore", {"COPLANAR_OVERLAP", "DUPLICATE_INSTANCE"}}}));
    EXPECT_EQ(ignored.exit_code, 0) << ignored.out;
    EXPECT_TRUE(with_code(ignored.report, "COPLANAR_OVERLAP").empty());
    EXPECT_EQ(ignored.report["issues"]["numErrors"], 0);
    const Lint only =
        run_lint("config_only", gltf.string() + config("only.json", {{"only", {"ALPHA_MODE"}}}));
    EXPECT_EQ(only.report["issues"]["messages"].size(),
              with_code(plain.report, "ALPHA_MODE").size());
    const Lint over =
        run_lint("config_override",
                 gltf.string() + config("override.json", {{"override", {{"ALPHA_MODE", 0}}}}) +
                     " --fail-on error");
    EXPECT_EQ(over.report["issues"]["numErrors"],
              plain.report["issues"]["numErrors"].get<int>() + 2);
    const Lint capped =
        run_lint("config_max", gltf.string() + config("max.json", {{"max-issues", 1}}));
    EXPECT_EQ(capped.report["issues"]["messages"].size(), 1u);
    EXPECT_TRUE(capped.report["issues"]["truncated"].get<bool>());
    const Lint warn = run_lint(
        "config_warn",
        gltf.string() +
            config("ignore2.json", {{"ignore", {"COPLANAR_OVERLAP", "DUPLICATE_INSTANCE"}}}) +
            " --fail-on warning");
    EXPECT_EQ(warn.exit_code, 1) << "ALPHA_MODE warnings remain";
}

void expect_one_error_line(const ds::test::ProcessResult& r, const std::string& what) {
    EXPECT_NE(r.exit_code, 0) << what;
    EXPECT_EQ(r.err.rfind("depthscope: error: ", 0), 0u) << what << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << ": " << r.err;
}

TEST(Lint, BadInputIsOneLineAndWritesNothing) {
    const auto dir = ds::test::fresh_dir("lint_bad");
    const auto out = dir / "out.json";
    std::ofstream(dir / "malformed.json") << "{\"ignore\": [";
    std::ofstream(dir / "unknown.json") << R"({"ignored": ["X"]})";
    std::ofstream(dir / "both.json") << R"({"ignore": ["A"], "only": ["B"]})";
    std::ofstream(dir / "severity.json") << R"({"override": {"ALPHA_MODE": 7}})";
    std::ofstream(dir / "broken.gltf") << "{ not json";
    const std::string json_out = " --json " + out.string();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"missing scene", "lint " + (dir / "missing.gltf").string() + json_out},
        {"broken scene", "lint " + (dir / "broken.gltf").string() + json_out},
        {"malformed config",
         "lint zfight --config " + (dir / "malformed.json").string() + json_out},
        {"unknown key", "lint zfight --config " + (dir / "unknown.json").string() + json_out},
        {"ignore and only", "lint zfight --config " + (dir / "both.json").string() + json_out},
        {"bad severity", "lint zfight --config " + (dir / "severity.json").string() + json_out},
        {"missing config", "lint zfight --config " + (dir / "none.json").string() + json_out},
        {"bad fail-on", "lint zfight --fail-on fatal" + json_out},
        {"unknown setting", "lint zfight --set no_such_knob=1" + json_out},
        {"no scene", "lint" + json_out},
        {"unwritable json", "lint zfight --json /proc/version/lint.json"},
        {"second scene missing", "lint zfight " + (dir / "missing.gltf").string() + json_out},
    };
    for (const auto& [what, args] : cases) {
        expect_one_error_line(run_depthscope(args), what);
        EXPECT_FALSE(std::filesystem::exists(out)) << what;
    }
}

}  // namespace
