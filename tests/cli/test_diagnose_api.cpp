// The API the inspector calls (capture/diagnose/diagnose_run.h), in-process on one validated
// renderer: each finding carries the pixels it covers (as many as its magnitude in pixels says,
// from the zfight pass's hits and equal_check's image), and the measurement knobs leave the image
// as the user's settings draw it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "capture/diagnose/checks.h"
#include "capture/diagnose/diagnose_run.h"
#include "capture/diagnose/finding.h"
#include "renderer/device_info.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kWidth = 320, kHeight = 180;

class DiagnoseApi : public test::SharedRenderer {
  protected:
    diagnose::Diagnosis run(const char* scene_name, const std::vector<std::string>& assignments) {
        const Settings settings = test::settings_of(assignments);
        scene_ = scene::load_scene(scene_name, settings);
        renderer_->set_scene(scene_);
        return diagnose::diagnose(*renderer_, scene_, scene_.camera, settings, {kWidth, kHeight});
    }
    scene::Scene scene_;
};

// Pixels ascending, each once, inside the frame; as many as a magnitude in px says.
void expect_pixels_match(const diagnose::Finding& f) {
    SCOPED_TRACE(f.code + ": " + f.message);
    EXPECT_TRUE(std::is_sorted(f.pixels.begin(), f.pixels.end()));
    EXPECT_EQ(std::adjacent_find(f.pixels.begin(), f.pixels.end()), f.pixels.end());
    if (!f.pixels.empty()) {
        EXPECT_LT(f.pixels.back(), kWidth * kHeight);
    }
    if (f.magnitude.unit == "px") {
        EXPECT_EQ(double(f.pixels.size()), f.magnitude.value);
    }
}

size_t count_code(const diagnose::Diagnosis& d, const std::string& code) {
    return size_t(std::count_if(d.findings.begin(), d.findings.end(),
                                [&](const diagnose::Finding& f) { return f.code == code; }));
}

TEST_F(DiagnoseApi, ZfightAndDecalFindingsCarryTheirPixels) {
    for (const auto& [scene_name, settings] :
         std::vector<std::pair<const char*, std::vector<std::string>>>{
             {"zfight", {}}, {"decals", {"decal_pass=off"}}}) {
        const diagnose::Diagnosis d = run(scene_name, settings);
        EXPECT_GT(count_code(d, "ZFIGHT") + count_code(d, "DECAL_ZFIGHT"), 0u) << scene_name;
        for (const diagnose::Finding& f : d.findings) {
            expect_pixels_match(f);
            if (f.code == "ZFIGHT" || f.code == "DECAL_ZFIGHT") {
                EXPECT_FALSE(f.pixels.empty());
            }
        }
        EXPECT_EQ(d.frames, 11u);
    }
}

// EQUAL_HOLES' pixels come from the equal_check image, its magnitude from the pass's counter.
TEST_F(DiagnoseApi, EqualHolesCarryTheImagesHolePixels) {
    const diagnose::Diagnosis d = run("atrium", {"invariant=off"});
    ASSERT_EQ(count_code(d, "EQUAL_HOLES"), 1u);
    for (const diagnose::Finding& f : d.findings) {
        expect_pixels_match(f);
        // Every finding but the shadow map's (the light's view) and occluded draws covers pixels.
        if (f.code == "EQUAL_HOLES" ||
            (f.code == "EARLY_Z_LOST" && f.message.find("light's view") == std::string::npos)) {
            EXPECT_FALSE(f.pixels.empty());
        }
    }
    EXPECT_EQ(d.findings.front().severity, diagnose::Severity::Error) << "ranked";
}

// Only measurement knobs: the measuring frame's image is the user's frame, byte for byte.
TEST_F(DiagnoseApi, TheMeasurementKnobsLeaveTheImageAsItWas) {
    for (const char* scene_name : {"atrium", "decals"}) {
        const Settings settings = test::settings_of({"decal_pass=off"});
        scene_ = scene::load_scene(scene_name, settings);
        renderer_->set_scene(scene_);
        std::vector<diagnose::SkippedDetector> skipped;
        const Settings measuring =
            diagnose::with_measurement_knobs(settings, device_info(*renderer_), skipped);
        EXPECT_TRUE(skipped.empty()) << skipped.front().reason;
        const RenderRequest request{.width = kWidth, .height = kHeight};
        renderer_->camera_cut();
        const FrameResult plain = renderer_->render(scene_.camera, settings, request);
        renderer_->camera_cut();
        const FrameResult measured = renderer_->render(scene_.camera, measuring, request);
        ASSERT_FALSE(plain.rgba8.empty());
        EXPECT_TRUE(plain.rgba8 == measured.rgba8) << scene_name;
    }
}

// ALPHA_COVERAGE on foliage: its grass (thin blades) loses coverage down the box chain, so the
// check names it, with preserve's fix; with alpha_mip_coverage=preserve the uploaded chain
// keeps level 0's coverage and nothing is found. The check reads the scene only (no frame).
TEST(DiagnoseAlphaCoverage, FiresOnFoliagesGrassWithBoxMipsAndNotWithPreserve) {
    const scene::Scene foliage = scene::load_scene("foliage", Settings{});
    const FrameResult none;
    auto check = [&](const std::vector<std::string>& assignments) {
        const Settings settings = test::settings_of(assignments);
        diagnose::CheckOutput out;
        diagnose::check_alpha_coverage(
            {.scene = foliage, .settings = settings, .measured = none, .advice_skipped = {}}, out);
        EXPECT_EQ(out.ran, std::vector<std::string>{"alpha_coverage"});
        return out.findings;
    };
    const std::vector<diagnose::Finding> box = check({});
    ASSERT_EQ(box.size(), 1u);
    const diagnose::Finding& f = box.front();
    std::printf("%s\nfix: %s\n", f.message.c_str(), f.fix.c_str());
    EXPECT_EQ(f.code, "ALPHA_COVERAGE");
    EXPECT_EQ(f.severity, diagnose::Severity::Warning);
    EXPECT_NE(f.message.find("material grass"), std::string::npos) << f.message;
    EXPECT_EQ(f.magnitude.unit, "%");
    EXPECT_GT(f.magnitude.value, 20.0);
    EXPECT_NE(f.fix.find("alpha_mip_coverage=preserve"), std::string::npos) << f.fix;
    ASSERT_FALSE(f.surfaces.empty());
    EXPECT_EQ(f.surfaces.front().material, "grass");
    EXPECT_TRUE(check({"alpha_mip_coverage=preserve"}).empty());
    // A lower cutoff keeps more of the blades' averaged alpha: no finding either.
    EXPECT_TRUE(check({"material_alpha_cutoff=grass=0.1"}).empty());
}

}  // namespace
