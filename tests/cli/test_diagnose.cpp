// depthscope diagnose through the real executable on lavapipe: the issue's five acceptance
// cases (the zfight scene's pairs, atrium's EQUAL holes without invariance, the overdraw
// scene's advice, the decals scene's overlays without the decal pass, atrium's lost early-Z
// without masked_split), a glTF this test writes (two coplanar quads), the JSON's shape,
// --fail-on's exit codes and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

namespace {

using ds::test::run_depthscope;
using nlohmann::json;

constexpr const char* kSize = " --size 320x180";

// `diagnose ARGS --json FILE`, exit 0 expected; the JSON.
json diagnose(const std::string& name, const std::string& args) {
    const auto path = ds::test::fresh_dir("diagnose_" + name) / "diagnosis.json";
    const auto r = run_depthscope(
        "diagnose --validate" + std::string(kSize) + " " + args + " --json " + path.string(), 300);
    EXPECT_EQ(r.exit_code, 0) << r.err << r.out;
    EXPECT_TRUE(std::regex_search(
        r.out, std::regex("\\n[0-9]+ errors?, [0-9]+ warnings?, [0-9]+ infos?, [0-9]+ hints?\\n")))
        << r.out;
    if (!std::filesystem::exists(path)) return json::object();
    return json::parse(ds::test::read_file(path));
}

std::vector<json> with_code(const json& d, const std::string& code) {
    std::vector<json> out;
    for (const json& m : d["issues"]["messages"])
        if (m["code"] == code) out.push_back(m);
    return out;
}

std::set<std::string> nodes_of(const json& finding) {
    std::set<std::string> out;
    for (const json& s : finding["surfaces"]) out.insert(s["node"].get<std::string>());
    return out;
}

std::string reason_skipped(const json& d, const std::string& detector) {
    for (const json& s : d["skipped"])
        if (s["detector"] == detector) return s["reason"];
    return "";
}

}  // namespace

// Every pair the zfight pass reports (capture's report.json, the same view and size) is a
// ZFIGHT error naming both surfaces, with its pixels as magnitude; the six exactly coplanar
// pairs are among them.
TEST(Diagnose, NamesTheZfightScenesFightingPairsAsItsReportListsThem) {
    const json d = diagnose("zfight", "--scene zfight");
    const auto dir = ds::test::fresh_dir("diagnose_zfight_capture") / "cap";
    ASSERT_EQ(run_depthscope("capture --scene zfight --set zfight=on" + std::string(kSize) +
                             " --out " + dir.string())
                  .exit_code,
              0);
    const json report = json::parse(ds::test::read_file(dir / "report.json"));
    std::set<std::set<std::string>> found;
    for (const json& f : with_code(d, "ZFIGHT")) {
        EXPECT_EQ(f["severity"], 0) << f.dump();
        EXPECT_EQ(f["magnitude"]["unit"], "px") << f.dump();
        EXPECT_EQ(f["detector"], "zfight");
        found.insert(nodes_of(f));
        for (const json& s : f["surfaces"])
            EXPECT_TRUE(s["pointer"].get<std::string>().starts_with("/nodes/")) << f.dump();
    }
    ASSERT_FALSE(report["zfight"]["pairs"].empty());
    for (const json& p : report["zfight"]["pairs"])
        EXPECT_TRUE(
            found.count({p["a"]["node"].get<std::string>(), p["b"]["node"].get<std::string>()}))
            << p.dump();
    int coplanar = 0;
    for (const auto& pair : found) coplanar += pair.begin()->starts_with("coplanar_a_");
    EXPECT_EQ(coplanar, 6);
}

// The edges scene's fan of rods fights at its hub between every pair of neighbours: beyond
// eight pairs of one pair of meshes the rest fold into one finding, and no pixel is lost.
TEST(Diagnose, FoldsManyPairsOfOneMeshPairIntoOneFinding) {
    const auto path = ds::test::fresh_dir("diagnose_edges") / "diagnosis.json";
    ASSERT_EQ(run_depthscope("diagnose --scene edges --size 640x360 --json " + path.string(), 300)
                  .exit_code,
              0);
    const json d = json::parse(ds::test::read_file(path));
    const auto dir = ds::test::fresh_dir("diagnose_edges_capture") / "cap";
    ASSERT_EQ(run_depthscope("capture --scene edges --set zfight=on --size 640x360 --resources "
                             "none --out " +
                             dir.string())
                  .exit_code,
              0);
    const json report = json::parse(ds::test::read_file(dir / "report.json"));
    double reported = 0, found = 0;
    for (const json& p : report["zfight"]["pairs"]) reported += p["pixels"].get<double>();
    const std::vector<json> fights = with_code(d, "ZFIGHT");
    int folded = 0;
    for (const json& f : fights) {
        found += f["magnitude"]["value"].get<double>();
        folded +=
            f["message"].get<std::string>().find(" more pairs of mesh rod") != std::string::npos;
    }
    ASSERT_GT(report["zfight"]["pairs"].size(), 9u) << "the view no longer shows the fan's hub";
    EXPECT_EQ(fights.size(), 9u);
    EXPECT_EQ(folded, 1);
    EXPECT_EQ(found, reported);
}

TEST(Diagnose, NamesAtriumsEqualHolesWithoutInvariance) {
    const json off = diagnose("atrium_invariant_off", "--scene atrium --set invariant=off");
    const auto holes = with_code(off, "EQUAL_HOLES");
    ASSERT_EQ(holes.size(), 1u) << off["issues"].dump(1);
    EXPECT_EQ(holes[0]["severity"], 0);
    EXPECT_GT(holes[0]["magnitude"]["value"].get<double>(), 1000.0);
    EXPECT_NE(holes[0]["message"].get<std::string>().find("not invariant"), std::string::npos);
    EXPECT_FALSE(holes[0]["surfaces"].empty());
    EXPECT_NE(holes[0]["fix"].get<std::string>().find("invariant=on"), std::string::npos);
    // With invariance: no holes, and the pipelines keep early-Z except the masked prepass one.
    const json on = diagnose("atrium", "--scene atrium");
    EXPECT_TRUE(with_code(on, "EQUAL_HOLES").empty()) << on["issues"].dump(1);
    for (const json& f : with_code(on, "EARLY_Z_LOST"))
        EXPECT_EQ(f["message"].get<std::string>().find("unsplit"), std::string::npos);
}

TEST(Diagnose, KeepsThePrepassOnTheOverdrawSceneWithItsOverdraw) {
    const json d = diagnose("overdraw", "--scene overdraw");
    const auto advice = with_code(d, "OVERDRAW");
    ASSERT_EQ(advice.size(), 1u) << d["issues"].dump(1);
    EXPECT_EQ(advice[0]["severity"], 2);  // info: the prepass is on, as it should be
    EXPECT_DOUBLE_EQ(advice[0]["magnitude"]["value"].get<double>(), 8.0);
    EXPECT_EQ(advice[0]["magnitude"]["unit"], "x");
    EXPECT_NE(advice[0]["message"].get<std::string>().find("keep the prepass"), std::string::npos);
    // The seven hidden layers are drawn for nothing.
    EXPECT_EQ(with_code(d, "OCCLUDED_DRAW").size(), 7u) << d["issues"].dump(1);
    // Without the prepass the same advice is a warning: forward shades 8 layers.
    const json off = diagnose("overdraw_off", "--scene overdraw --set prepass=off");
    const auto warned = with_code(off, "OVERDRAW");
    ASSERT_EQ(warned.size(), 1u);
    EXPECT_EQ(warned[0]["severity"], 1);
    EXPECT_EQ(reason_skipped(off, "zfight"), "prepass off");
}

TEST(Diagnose, NamesTheDecalsFightingTheirWallsWithoutTheDecalPass) {
    const json off = diagnose("decals_off", "--scene decals --set decal_pass=off");
    std::set<std::set<std::string>> pairs;
    for (const json& f : with_code(off, "DECAL_ZFIGHT")) {
        EXPECT_EQ(f["severity"], 0);
        pairs.insert(nodes_of(f));
    }
    EXPECT_TRUE(pairs.count({"decal_red_opaque", "back_wall"})) << off["issues"].dump(1);
    EXPECT_TRUE(pairs.count({"decal_yellow_opaque", "floor"})) << off["issues"].dump(1);
    EXPECT_TRUE(with_code(off, "ZFIGHT").empty()) << "decal pairs are DECAL_ZFIGHT only";
    const json on = diagnose("decals_on", "--scene decals");
    EXPECT_TRUE(with_code(on, "DECAL_ZFIGHT").empty()) << on["issues"].dump(1);
    EXPECT_TRUE(with_code(on, "ZFIGHT").empty()) << on["issues"].dump(1);
}

TEST(Diagnose, NamesAtriumsLostEarlyZWithoutMaskedSplit) {
    const json d = diagnose("atrium_unsplit", "--scene atrium --set masked_split=off");
    bool unsplit = false;
    for (const json& f : with_code(d, "EARLY_Z_LOST")) {
        EXPECT_EQ(f["severity"], 1);
        if (f["message"].get<std::string>().starts_with("depth_prepass unsplit loses early-Z")) {
            unsplit = true;
            EXPECT_EQ(f["magnitude"]["unit"], "fragments");
            EXPECT_GT(f["magnitude"]["value"].get<double>(), 0.0);
            EXPECT_NE(f["fix"].get<std::string>().find("masked_split=on"), std::string::npos);
            EXPECT_FALSE(f["surfaces"].empty());
        }
    }
    EXPECT_TRUE(unsplit) << d["issues"].dump(1);
}

// The report's shape (glTF-Validator's issues plus depthscope's fields), its counts, its
// ranking and what it ran on; depth_compare=greater_or_equal leaves equal_check out, saying why.
TEST(Diagnose, TheJsonHasTheReportShapeAndItsCountsMatch) {
    const json d = diagnose("shape",
                            "--scene decals --set decal_pass=off "
                            "--set depth_compare=greater_or_equal --look-at 0,1.5,6:0,1.5,-3");
    ASSERT_TRUE(d.contains("issues")) << d.dump();
    const json& issues = d["issues"];
    int counts[4] = {0, 0, 0, 0};
    int last_severity = 0;
    for (const json& m : issues["messages"]) {
        for (const char* key :
             {"code", "message", "severity", "pointer", "magnitude", "surfaces", "fix", "detector"})
            EXPECT_TRUE(m.contains(key)) << key << " in " << m.dump();
        const int severity = m["severity"];
        ASSERT_GE(severity, 0);
        ASSERT_LE(severity, 3);
        EXPECT_GE(severity, last_severity) << "ranked by severity";
        last_severity = severity;
        ++counts[severity];
        EXPECT_TRUE(m["magnitude"].contains("value") && m["magnitude"].contains("unit"));
        for (const json& s : m["surfaces"])
            for (const char* key : {"mesh", "material", "node", "pointer"})
                EXPECT_TRUE(s.contains(key));
    }
    EXPECT_EQ(issues["numErrors"], counts[0]);
    EXPECT_EQ(issues["numWarnings"], counts[1]);
    EXPECT_EQ(issues["numInfos"], counts[2]);
    EXPECT_EQ(issues["numHints"], counts[3]);
    EXPECT_GT(counts[0], 0) << "the overlays fight";
    EXPECT_EQ(d["scene"]["name"], "decals");
    EXPECT_EQ(d["size"]["width"], 320);
    EXPECT_EQ(d["size"]["height"], 180);
    EXPECT_EQ(d["settings"]["decal_pass"], "off");
    EXPECT_EQ(d["settings"]["zfight"], "off") << "the user's settings, not the measuring frame's";
    EXPECT_FLOAT_EQ(d["camera"]["position"][2].get<float>(), 6.0f);
    EXPECT_EQ(d["frames"], 11);
    EXPECT_EQ(reason_skipped(d, "equal_check"), "depth_compare is not equal");
    // The decals' MASK overlays keep their coverage down the mips: checked, nothing found.
    EXPECT_EQ(reason_skipped(d, "alpha_coverage"), "");
    EXPECT_NE(std::find(d["detectors"].begin(), d["detectors"].end(), "alpha_coverage"),
              d["detectors"].end());
    EXPECT_TRUE(with_code(d, "ALPHA_COVERAGE").empty());
    for (const char* knob : {"zfight=on", "count_fragments=on", "count_draws=on"})
        EXPECT_NE(std::find(d["measurement_knobs"].begin(), d["measurement_knobs"].end(), knob),
                  d["measurement_knobs"].end())
            << knob;
}

TEST(Diagnose, FailOnSetsTheExitCodeBySeverity) {
    const std::string overdraw = "diagnose --scene overdraw --size 64x36 --fail-on ";
    // The overdraw scene: occluded layers (warnings), no error.
    EXPECT_EQ(run_depthscope(overdraw + "error").exit_code, 0);
    EXPECT_EQ(run_depthscope(overdraw + "warning").exit_code, 1);
    const auto plain = run_depthscope("diagnose --scene zfight --size 64x36");
    EXPECT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_NE(plain.out.find("ZFIGHT"), std::string::npos) << plain.out;
    EXPECT_EQ(run_depthscope("diagnose --scene zfight --size 64x36 --fail-on error").exit_code, 1);
}

TEST(Diagnose, BadInputIsOneLineAndWritesNothing) {
    const auto dir = ds::test::fresh_dir("diagnose_bad");
    const std::string json_arg = " --json " + (dir / "d.json").string();
    struct Case {
        std::string args;
        int code;
        std::string mention;
    };
    const std::vector<Case> cases = {
        {"--scene no_such_scene", 1, "no_such_scene"},
        {"--size 0x10", 2, "--size"},
        {"--size 10", 2, "--size"},
        {"--set no_such_knob=1", 2, "no_such_knob"},
        {"--set zfight=maybe", 2, "zfight"},
        {"--fail-on info", 2, "--fail-on"},
        {"--look-at 1,2,3", 2, "--look-at"},
        {"--look-at 1,2,3:1,2,3", 2, "--look-at"},
        {"--look-at 1,2,x:0,0,0", 2, "--look-at"},
        {"--camera-of " + (dir / "no_capture").string(), 1, "report.json"},
        {"--camera no_such_camera", 2, "no_such_camera"},
    };
    for (const Case& c : cases) {
        const auto r = run_depthscope("diagnose --size 32x18 " + c.args + json_arg);
        SCOPED_TRACE(c.args);
        ds::test::expect_one_error_line(r, c.code, c.mention);
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_FALSE(std::filesystem::exists(dir / "d.json"));
    }
    // Unwritable --json targets: a directory, a missing folder.
    for (const auto& target : {dir, dir / "missing" / "d.json"}) {
        const auto r =
            run_depthscope("diagnose --scene overdraw --size 32x18 --json " + target.string());
        ds::test::expect_one_error_line(r, 1, "--json");
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
}

// A scene this test writes: two exactly coplanar quads with crossing diagonals (nodes 1 and 2;
// node 0 the camera), so the classifier calls neither a decal (each lies on the other).
TEST(Diagnose, NamesBothNodesOfACoplanarPairInAFileWithTheirPointers) {
    const auto dir = ds::test::fresh_dir("diagnose_file");
    const float positions[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const float normals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    const uint16_t indices[] = {0, 1, 2, 0, 2, 3, 0, 1, 3, 1, 2, 3};
    std::string bin(sizeof positions + sizeof normals + sizeof indices, '\0');
    std::memcpy(bin.data(), positions, sizeof positions);
    std::memcpy(bin.data() + 48, normals, sizeof normals);
    std::memcpy(bin.data() + 96, indices, sizeof indices);
    std::ofstream(dir / "pair.bin", std::ios::binary) << bin;
    json position = {{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}};
    json normal = position;
    position["min"] = {-1.0, -1.0, 0.0};
    position["max"] = {1.0, 1.0, 0.0};
    normal["byteOffset"] = 48;
    json gltf = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0, 1, 2}}}}},
        {"nodes",
         {{{"name", "eye"}, {"camera", 0}, {"translation", {0.0, 0.0, 3.0}}},
          {{"name", "floor_tiles"}, {"mesh", 0}},
          {{"name", "floor_overlay"}, {"mesh", 1}}}},
        {"cameras",
         {{{"type", "perspective"},
           {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 100.0}}}}}},
        {"meshes",
         {{{"name", "tiles"},
           {"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}}}}},
          {{"name", "overlay"},
           {"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 3}}}}}}},
        {"buffers", {{{"uri", "pair.bin"}, {"byteLength", bin.size()}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 96}},
          {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 24}}}},
        {"accessors",
         {position,
          normal,
          {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
          {{"bufferView", 1},
           {"byteOffset", 12},
           {"componentType", 5123},
           {"count", 6},
           {"type", "SCALAR"}}}},
    };
    std::ofstream(dir / "pair.gltf") << gltf.dump();
    const json d = diagnose("file_run", "--scene " + (dir / "pair.gltf").string());
    const auto fights = with_code(d, "ZFIGHT");
    ASSERT_EQ(fights.size(), 1u) << d["issues"].dump(1);
    EXPECT_EQ(nodes_of(fights[0]), (std::set<std::string>{"floor_tiles", "floor_overlay"}));
    std::set<std::string> pointers;
    for (const json& s : fights[0]["surfaces"]) pointers.insert(s["pointer"].get<std::string>());
    EXPECT_EQ(pointers, (std::set<std::string>{"/nodes/1", "/nodes/2"}));
    EXPECT_EQ(fights[0]["pointer"], "/nodes/1");
    EXPECT_GT(fights[0]["magnitude"]["value"].get<double>(), 1000.0);
}
