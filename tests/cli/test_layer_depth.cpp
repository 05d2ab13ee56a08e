// The layer's Z-fight and EQUAL checks (`depthscope layer --set zfight=on --set
// equal_check=on`) on depthscope itself, with its own checks off, against depthscope's own
// zfight and equal_check of the same frame run without the layer: the oracle.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/layer_test_helpers.h"
#include "tests/support/run_process.h"

namespace ds::test::layer_depth {
namespace {

using nlohmann::json;

// depthscope capture under the layer with its checks on; `validate`: the validation layer too.
json layer_checks(const std::string& scene, const std::string& sets,
                  const std::filesystem::path& dir, const std::string& app_flags = "") {
    const ProcessResult r = run_depthscope(
        "layer --frame 1 --set zfight=on --set equal_check=on --out " + (dir / "layer").string() +
        " -- " DS_EXECUTABLE " capture --resources none " + app_flags + " --scene " + scene + " " +
        kLayerTestSize + " " + sets + " --out " + (dir / "app").string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_report(dir / "layer");
}

json own_checks(const std::string& scene, const std::string& sets,
                const std::filesystem::path& dir) {
    const ProcessResult r =
        run_depthscope("capture --resources none --scene " + scene + " " + kLayerTestSize + " " +
                       sets + " --set zfight=on --set equal_check=on --set count_draws=on --out " +
                       (dir / "own").string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_report(dir / "own");
}

// A pair as both reports can say it: the meshes of its two instances (sorted), its pixels and
// least gap. depthscope names instances by node; the layer by draw and gl_InstanceIndex, and a
// draw by its debug label, a node of its group's mesh.
using Pair = std::tuple<std::string, std::string, uint64_t, uint32_t>;

Pair make_pair(std::string a, std::string b, uint64_t pixels, uint32_t steps) {
    if (b < a) std::swap(a, b);
    return {a, b, pixels, steps};
}

// depthscope's own pairs between two instances (it also counts overlapping triangles of one
// instance, a == b, which the layer's (draw, instance) pairs leave out by definition).
std::vector<Pair> own_pairs(const json& own) {
    std::vector<Pair> out;
    for (const json& p : own.at("zfight").at("pairs"))
        if (p.at("a") != p.at("b"))
            out.push_back(make_pair(p.at("a").at("mesh"), p.at("b").at("mesh"), p.at("pixels"),
                                    p.at("min_steps")));
    std::sort(out.begin(), out.end());
    return out;
}

bool own_has_self_pairs(const json& own) {
    for (const json& p : own.at("zfight").at("pairs"))
        if (p.at("a") == p.at("b")) return true;
    return false;
}

// The layer's pairs of the camera's prepass, meshes from the own report's draw groups.
std::vector<Pair> layer_pairs(const json& layer, const json& own) {
    std::map<std::string, std::string> mesh_of;  // group label (node) -> mesh
    for (const json& d : own.at("draws")) mesh_of[d.at("node")] = d.at("mesh");
    std::vector<Pair> out;
    for (const json& p : layer.at("zfight").at("pairs")) {
        if (p.at("pass") != "depth_prepass") continue;
        EXPECT_TRUE(p.at("a").contains("instance")) << p.dump();
        out.push_back(make_pair(mesh_of[p.at("a").at("name")], mesh_of[p.at("b").at("name")],
                                p.at("pixels"), p.at("min_steps")));
    }
    std::sort(out.begin(), out.end());
    return out;
}

uint64_t prepass_pixels(const json& layer) {
    for (const json& p : layer.at("zfight").at("passes"))
        if (p.at("pass") == "depth_prepass") return p.at("pixels");
    ADD_FAILURE() << "no depth_prepass in " << layer.at("zfight").dump();
    return 0;
}

// One frame, both checks: the pairs (with their pixels and least steps) and the pixels with a
// competitor equal depthscope's own zfight; the holes and ties its own equal_check. zfight:
// coplanar pairs; decals without their pass: decals fight and tie with their bases; atrium
// with a forward vertex shader that is not invariant: holes.
class LayerDepthOracle
    : public testing::TestWithParam<std::tuple<const char*, const char*, const char*>> {};

TEST_P(LayerDepthOracle, PairsHolesAndTiesEqualDepthscopesOwn) {
    const auto [scene, sets, expected] = GetParam();
    const auto dir = fresh_dir(std::string("layer_depth_") + scene);
    const json layer = layer_checks(scene, sets, dir);
    const json own = own_checks(scene, sets, dir);
    const auto want = own_pairs(own);
    EXPECT_EQ(layer_pairs(layer, own), want);
    if (!own_has_self_pairs(own)) {
        EXPECT_EQ(prepass_pixels(layer), own.at("zfight").at("pixels").get<uint64_t>());
    }
    EXPECT_FALSE(layer.at("zfight").contains("dropped_records"));
    for (const char* key : {"holes", "multiple"})
        EXPECT_EQ(layer.at("equal_check").at(key), own.at("equal_check").at(key)) << key;
    // What each scene is there for is found at all.
    const std::string what = expected;
    if (what == "pairs") {
        EXPECT_FALSE(want.empty());
    } else {
        EXPECT_GT(own.at("equal_check").at(what).get<uint64_t>(), 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(BuiltInScenes, LayerDepthOracle,
                         testing::Values(std::make_tuple("zfight", "", "pairs"),
                                         std::make_tuple("decals", "--set decal_pass=off",
                                                         "multiple"),
                                         std::make_tuple("atrium", "--set invariant=off", "holes")),
                         [](const auto& info) { return std::string(std::get<0>(info.param)); });

// No coplanar surfaces: no pair in any depth format; the application's image unchanged and no
// validation message added with the checks on.
class LayerNoFight : public testing::TestWithParam<const char*> {};

TEST_P(LayerNoFight, OverdrawHasNoPairInAnyDepthFormat) {
    const std::string sets = std::string("--set depth_format=") + GetParam();
    const auto dir = fresh_dir(std::string("layer_nofight_") + GetParam());
    const json layer = layer_checks("overdraw", sets, dir, "--validate");
    EXPECT_EQ(layer.at("zfight").at("pairs").size(), 0u) << layer.at("zfight").dump();
    EXPECT_GT(layer.at("zfight").at("passes").size(), 0u);
    EXPECT_EQ(layer.at("equal_check").at("holes"), 0);
    EXPECT_EQ(layer.at("equal_check").at("multiple"), 0);
    EXPECT_GT(layer.at("cost").at("depth_record_bytes").get<uint64_t>(), 0u);
    if (std::string(GetParam()) != "d32f") return;  // the image: once is enough
    const ProcessResult plain =
        run_depthscope("capture --resources none --scene overdraw " + std::string(kLayerTestSize) +
                       " " + sets + " --validate --out " + (dir / "plain").string());
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_EQ(read_file(dir / "app" / "final.png"), read_file(dir / "plain" / "final.png"));
}

INSTANTIATE_TEST_SUITE_P(DepthFormats, LayerNoFight, testing::Values("d32f", "d24", "d16"));

TEST(LayerDepth, EverySurvivalShaderPassesSpirvVal) {
    const auto dir = fresh_dir("layer_survival_val");
    const json layer = layer_checks("foliage", "", dir);
    size_t modules = 0;
    for (const json& p : layer.at("pipelines")) {
        if (!p.contains("survival_spirv")) continue;
        const auto file = dir / "layer" / p.at("survival_spirv").get<std::string>();
        const ProcessResult r =
            run_command("spirv-val --target-env vulkan1.3 '" + file.string() + "'");
        EXPECT_EQ(r.exit_code, 0) << file << "\n" << r.out << r.err;
        ++modules;
    }
    EXPECT_GT(modules, 1u);
}

}  // namespace
}  // namespace ds::test::layer_depth
