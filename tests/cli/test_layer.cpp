// depthscope's Vulkan layer (`depthscope layer`, VK_LAYER_DEPTHSCOPE_diagnostics) on depthscope
// itself: the oracle (the layer's per-draw counts, summed per draw group label, equal
// depthscope's own count_draws / count_fragments of the same frame), the application's output
// unchanged, no validation message added, every instrumented shader valid SPIR-V.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <tuple>

#include <nlohmann/json.hpp>

#include "tests/cli/layer_test_helpers.h"
#include "tests/support/run_process.h"

namespace ds::test {
namespace {

using nlohmann::json;

// depthscope capture --resources none submits one frame (with resources, a second submission
// reads the images back): the layer captures it.
json layer_capture(const std::string& scene, const std::string& sets,
                   const std::filesystem::path& dir, const std::string& app_flags = "") {
    const auto app_out = dir / "app";
    const ProcessResult r =
        run_depthscope("layer --frame 1 --out " + (dir / "layer").string() +
                       " -- " DS_EXECUTABLE " capture --resources none " + app_flags + " --scene " +
                       scene + " " + kLayerTestSize + " " + sets + " --out " + app_out.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_report(dir / "layer");
}

// (pass, draw group name) -> counts.
using Key = std::pair<std::string, std::string>;
struct Counts {
    uint64_t shaded = 0, discarded = 0, samples_passed = 0;
};

std::map<Key, Counts> layer_counts(const json& report) {
    std::map<Key, Counts> out;
    for (const json& d : report.at("draws")) {
        EXPECT_FALSE(d.contains("not_analysed")) << d.dump();
        if (d.contains("not_analysed")) continue;
        const std::string pass = report.at("passes").at(d.at("pass").get<size_t>()).at("name");
        if (pass != "depth_prepass" && pass != "forward") continue;
        Counts& c = out[{pass, d.at("name")}];
        c.shaded += d.at("shaded").get<uint64_t>();
        c.discarded += d.at("discarded").get<uint64_t>();
        c.samples_passed += d.at("samples_passed").get<uint64_t>();
    }
    return out;
}

// depthscope's own per-group numbers: shaded per pass, samples passed (the prepass's queries).
std::map<Key, Counts> own_counts(const json& report) {
    std::map<Key, Counts> out;
    for (const json& d : report.at("draws")) {
        const std::string node = d.at("node");
        for (const char* pass : {"depth_prepass", "forward"}) {
            const json& shaded = d.at("shaded_fragments").at(pass);
            if (!shaded.is_null()) out[{pass, node}].shaded += shaded.get<uint64_t>();
        }
        if (!d.at("samples_passed").is_null())
            out[{"depth_prepass", node}].samples_passed += d.at("samples_passed").get<uint64_t>();
    }
    return out;
}

uint64_t own_pass_total(const json& report, const std::string& pass, const char* counter) {
    for (const json& p : report.at("passes"))
        if (p.at("name") == pass) return p.at(counter).get<uint64_t>();
    ADD_FAILURE() << "no pass " << pass;
    return 0;
}

class LayerOracle : public testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(LayerOracle, PerGroupCountsEqualDepthscopesOwn) {
    const auto [scene, sets] = GetParam();
    const auto dir = fresh_dir(std::string("layer_oracle_") + scene);
    const json layer = layer_capture(scene, sets, dir);
    const ProcessResult own = run_depthscope(
        "capture --scene " + std::string(scene) + " " + kLayerTestSize + " " + sets +
        " --set count_draws=on --set count_fragments=on --out " + (dir / "own").string());
    ASSERT_EQ(own.exit_code, 0) << own.err;
    const json mine = read_report(dir / "own");
    const auto a = layer_counts(layer), b = own_counts(mine);
    ASSERT_FALSE(b.empty());
    size_t compared = 0;
    for (const auto& [key, want] : b) {
        const Counts got = a.count(key) ? a.at(key) : Counts{};
        EXPECT_EQ(got.shaded, want.shaded) << key.first << " / " << key.second;
        if (key.first == "depth_prepass") {
            EXPECT_EQ(got.samples_passed, want.samples_passed) << key.second;
        }
        ++compared;
    }
    for (const auto& [key, got] : a) EXPECT_TRUE(b.count(key)) << key.first << " / " << key.second;
    // Discards: depthscope counts them per pass.
    for (const char* pass : {"depth_prepass", "forward"}) {
        uint64_t discarded = 0;
        for (const auto& [key, c] : a)
            if (key.first == pass) discarded += c.discarded;
        EXPECT_EQ(discarded, own_pass_total(mine, pass, "discarded_fragments")) << pass;
    }
    EXPECT_GT(compared, 2u);
}

INSTANTIATE_TEST_SUITE_P(BuiltInScenes, LayerOracle,
                         testing::Values(std::make_tuple("overdraw", ""),
                                         std::make_tuple("foliage", ""),
                                         std::make_tuple("atrium", ""),
                                         std::make_tuple("decals", "--set decal_pass=off")),
                         [](const auto& info) { return std::string(std::get<0>(info.param)); });

class LayerUnchanged : public testing::TestWithParam<const char*> {};

// Alpha to coverage at msaa 4: coverage comes from the shader, so the layer must not move the
// depth test before it (it did: final.png differed).
TEST_P(LayerUnchanged, LeavesTheApplicationsOutputUnchangedAndAddsNoValidationMessage) {
    const std::string sets = GetParam();
    const auto dir = fresh_dir("layer_unchanged_" + std::to_string(sets.size()));
    // --validate: any validation message makes depthscope exit 3 (the layer sits before it).
    const json layer = layer_capture("foliage", sets, dir, "--validate");
    ASSERT_FALSE(layer.at("draws").empty());
    const ProcessResult plain =
        run_depthscope("capture --scene foliage " + std::string(kLayerTestSize) + " " + sets +
                       " --validate --out " + (dir / "plain").string());
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_EQ(read_file(dir / "app" / "final.png"), read_file(dir / "plain" / "final.png"));
}

std::string unchanged_name(const testing::TestParamInfo<const char*>& info) {
    const char* names[] = {"Default", "AlphaToCoverage", "SubpassPath"};
    return names[info.index];
}

// Also seed 002's subpass path: a render pass of two subpasses with input attachments.
INSTANTIATE_TEST_SUITE_P(Foliage, LayerUnchanged,
                         testing::Values("", "--set msaa=4 --set alpha_to_coverage=on",
                                         "--set render_path=subpass --set msaa=4"),
                         unchanged_name);

TEST(Layer, EveryInstrumentedShaderPassesSpirvVal) {
    const auto dir = fresh_dir("layer_spirv_val");
    const json layer = layer_capture("atrium", "", dir);
    size_t modules = 0;
    for (const json& p : layer.at("pipelines"))
        for (const char* key : {"instrumented_spirv", "measurement_spirv"}) {
            if (!p.contains(key)) continue;
            const auto file = dir / "layer" / p.at(key).get<std::string>();
            const ProcessResult r =
                run_command("spirv-val --target-env vulkan1.3 '" + file.string() + "'");
            EXPECT_EQ(r.exit_code, 0) << file << "\n" << r.out << r.err;
            ++modules;
        }
    // Every pipeline has a measurement shader; those with a fragment shader a rewrite of it.
    EXPECT_GT(modules, layer.at("pipelines").size());
}

}  // namespace
}  // namespace ds::test
