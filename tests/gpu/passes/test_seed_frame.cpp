// The seed frame (seed 000) on the atrium, through the Renderer facade with validation on
// (synchronization validation included): facts the frame must show, not golden images.
#include <stb/stb_image_write.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "renderer/shader/compiler.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;
using test::differing_pixels;
using test::names;

constexpr uint32_t kWidth = 320, kHeight = 180;

// One renderer and the atrium for every test: device and pipeline creation dominate on
// lavapipe.
class SeedFrame : public test::SharedScene {
  protected:
    static void SetUpTestSuite() { set_up_with("atrium"); }

    // `assignments`: "name=value" each.
    static FrameResult render(const std::vector<std::string>& assignments, uint32_t w = kWidth,
                              uint32_t h = kHeight) {
        return renderer_->render(scene_->camera, test::settings_of(assignments),
                                 {.width = w, .height = h});
    }
};

const PassResult* find_pass(const FrameResult& f, const std::string& name) {
    for (const PassResult& p : f.passes)
        if (p.name == name) return &p;
    return nullptr;
}

uint64_t shaded(const FrameResult& f, const std::string& pass) {
    const PassResult* p = find_pass(f, pass);
    if (!p || !p->shaded_fragments) {
        ADD_FAILURE() << pass << " has no shaded_fragments";
        return 0;
    }
    return *p->shaded_fragments;
}

// Where to write images to look at: $DS_TEST_IMAGES, else the temp directory.
std::string image_path(const std::string& name) {
    const char* dir = std::getenv("DS_TEST_IMAGES");
    return (std::filesystem::path(dir ? dir : std::filesystem::temp_directory_path().c_str()) /
            ("ds_" + name + ".png"))
        .string();
}

void write_png(const FrameResult& f, const std::string& name) {
    stbi_write_png(image_path(name).c_str(), int(f.width), int(f.height), 4, f.rgba8.data(),
                   int(f.width * 4));
}

TEST_F(SeedFrame, PassOrderAndSkips) {
    const FrameResult on = render({});
    EXPECT_EQ(names(on), (std::vector<std::string>{"shadow", "depth_prepass", "gtao", "ao_spatial",
                                                   "ao_temporal", "contact_shadows", "forward",
                                                   "skybox", "decals", "transparent", "tonemap"}));
    EXPECT_TRUE(on.skipped.empty());
    const std::string on_dump = renderer_->graph_dump();
    const FrameResult off = render({"prepass=off", "shadows=off", "sky=off"});
    EXPECT_EQ(names(off),
              (std::vector<std::string>{"forward", "decals", "transparent", "tonemap"}));
    EXPECT_EQ(off.skipped,
              (std::vector<std::string>{
                  "shadow: skipped (shadows=off)", "depth_prepass: skipped (prepass=off)",
                  "gtao: skipped (prepass off)", "ao_spatial: skipped (prepass off)",
                  "ao_temporal: skipped (prepass off)", "contact_shadows: skipped (prepass off)",
                  "skybox: skipped (sky=off)"}));
    for (const PassResult& p : on.passes) EXPECT_FALSE(p.shaded_fragments) << p.name;
    EXPECT_GT(find_pass(on, "forward")->vertex_shader_invocations, 0u);
    EXPECT_NE(on_dump.find("depth_prepass"), std::string::npos);
    write_png(on, "atrium");
}

// Every structural combination, with and without the counting variants. Besides being
// validation-clean (synchronization included), each covers the same pixels, and with the
// prepass and EQUAL forward shades each covered pixel once, whatever the depth convention and
// the prepass split.
TEST_F(SeedFrame, EveryStructuralCombinationIsValidationClean) {
    std::optional<uint64_t> covered;
    for (const char* prepass : {"on", "off"})
        for (const char* compare : {"equal", "greater_or_equal"})
            for (const char* split : {"on", "off"})
                for (const char* reverse : {"on", "off"})
                    for (const char* count : {"on", "off"}) {
                        const std::vector<std::string> s = {
                            std::string("prepass=") + prepass,
                            std::string("depth_compare=") + compare,
                            std::string("masked_split=") + split,
                            std::string("reverse_z=") + reverse,
                            std::string("count_fragments=") + count};
                        SCOPED_TRACE(s[0] + " " + s[1] + " " + s[2] + " " + s[3] + " " + s[4]);
                        const FrameResult f = render(s, 160, 90);
                        ASSERT_TRUE(f.covered_pixels);
                        if (!covered) covered = f.covered_pixels;
                        EXPECT_EQ(f.covered_pixels, covered);
                        if (s[0] == "prepass=on" && s[4] == "count_fragments=on") {
                            const double fwd = double(shaded(f, "forward"));
                            EXPECT_GE(fwd, 0.98 * double(*covered));
                            // greater_or_equal keeps MASK's discard, whose late depth test
                            // comes after the count: hidden leaves count there.
                            if (s[1] == "depth_compare=equal") {
                                EXPECT_LE(fwd, 1.02 * double(*covered));
                            }
                        }
                        EXPECT_EQ(renderer_->validation_message_count(), 0u);
                    }
}

// Prepass on: EQUAL keeps exactly the visible fragment of each pixel. Off: the atrium's
// authored (not front-to-back) order makes forward shade the hidden layers too.
TEST_F(SeedFrame, ShadedFragmentsShowWhatThePrepassSaves) {
    const FrameResult on = render({"count_fragments=on"});
    const FrameResult off = render({"count_fragments=on", "prepass=off"});
    ASSERT_TRUE(on.covered_pixels && off.covered_pixels);
    const double covered = double(*on.covered_pixels);
    EXPECT_EQ(*on.covered_pixels, *off.covered_pixels) << "the same surfaces cover the view";
    const double fwd_on = double(shaded(on, "forward"));
    const double fwd_off = double(shaded(off, "forward"));
    std::printf(
        "covered %.0f; forward shaded: prepass on %.0f (%.4fx), off %.0f (%.3fx); "
        "prepass %llu, decals %llu\n",
        covered, fwd_on, fwd_on / covered, fwd_off, fwd_off / covered,
        (unsigned long long)shaded(on, "depth_prepass"), (unsigned long long)shaded(on, "decals"));
    EXPECT_LE(fwd_on, 1.02 * covered);
    EXPECT_GE(fwd_on, 0.98 * covered) << "EQUAL must not reject visible fragments";
    EXPECT_GE(fwd_off, 2.0 * covered);
    // In the scene's authored order the prepass shades exactly what forward did without it;
    // front to back (prepass_sort, the default) it shades fewer hidden layers.
    const FrameResult authored = render({"count_fragments=on", "prepass_sort=off"});
    EXPECT_EQ(shaded(authored, "depth_prepass"), shaded(off, "forward"));
    EXPECT_LT(shaded(on, "depth_prepass"), shaded(authored, "depth_prepass"));
    EXPECT_GE(double(shaded(on, "depth_prepass")), covered);
    // Decals (the atrium's are BLEND): shaded once by the decals pass, the same fragments with
    // or without the prepass, and the same ones the transparent pass shades with decal_pass=off.
    EXPECT_GT(shaded(on, "decals"), 0u);
    EXPECT_EQ(shaded(on, "transparent"), 0u) << "the atrium's only BLEND surfaces are decals";
    EXPECT_EQ(shaded(on, "decals"), shaded(off, "decals"));
    const FrameResult drawn_as_transparent = render({"count_fragments=on", "decal_pass=off"});
    EXPECT_EQ(shaded(drawn_as_transparent, "transparent"), shaded(on, "decals"));
}

// The prepass changes how the image is made, not the image (seed 004's acceptance), with
// either forward depth test and either depth convention.
TEST_F(SeedFrame, PrepassOnAndOffGiveTheSameImage) {
    for (const char* reverse : {"on", "off"}) {
        const std::vector<std::string> common = {"gtao=off", "contact_shadows=off",
                                                 std::string("reverse_z=") + reverse};
        auto with = [&](const char* assignment) {
            std::vector<std::string> s = common;
            s.push_back(assignment);
            return render(s);
        };
        const FrameResult off = with("prepass=off");
        for (const char* compare : {"depth_compare=equal", "depth_compare=greater_or_equal"}) {
            const FrameResult on = with(compare);
            const size_t total = size_t(on.width) * on.height;
            const size_t differ = differing_pixels(on, off, 8);
            std::printf(
                "reverse_z=%s %s: prepass on/off differ in %zu of %zu pixels by more "
                "than 8/255 (%.4f%%), %zu by more than 2\n",
                reverse, compare, differ, total, 100.0 * double(differ) / double(total),
                differing_pixels(on, off, 2));
            EXPECT_LT(differ, total / 1000) << "reverse_z=" << reverse << " " << compare;
            if (std::string(reverse) == "on" && std::string(compare) == "depth_compare=equal") {
                write_png(on, "prepass_on");
                write_png(off, "prepass_off");
            }
        }
    }
}

// Without `invariant` and with a different expression, EQUAL rejects visible fragments.
TEST_F(SeedFrame, WithoutInvarianceEqualRejectsVisibleFragments) {
    const FrameResult f = render({"count_fragments=on", "invariant=off"});
    ASSERT_TRUE(f.covered_pixels);
    const double covered = double(*f.covered_pixels);
    const double fwd = double(shaded(f, "forward"));
    std::printf("invariant=off: forward shaded %.0f of %.0f covered (%.3f)\n", fwd, covered,
                fwd / covered);
    EXPECT_LT(fwd, 0.95 * covered);
    write_png(f, "invariant_off");
}

// Two sizes in one process, and back: the graph and the imported images follow.
TEST_F(SeedFrame, TwoSizesInOneProcess) {
    const FrameResult a = render({}, 160, 90);
    const FrameResult b = render({}, 200, 120);
    const FrameResult c = render({}, 160, 90);
    EXPECT_EQ(b.rgba8.size(), size_t(200) * 120 * 4);
    EXPECT_EQ(a.rgba8.size(), c.rgba8.size());
    // The temporal AO restarted after each resize, so the two 160x90 frames match closely.
    EXPECT_LT(differing_pixels(a, c, 8), size_t(160) * 90 / 100);
}

}  // namespace

namespace {

// Hot reload (DESIGN decision 10): a shader that does not compile throws with its file and
// line and leaves every pipeline as it was; once fixed, the rebuild goes through.
TEST(SeedFrameReload, BrokenShaderKeepsThePipelines) {
    namespace fs = std::filesystem;
    const fs::path root =
        fs::temp_directory_path() / ("ds_passes_shaders_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::copy(ds::shader::Compiler::default_shader_root(), root, fs::copy_options::recursive);
    ::setenv("DEPTHSCOPE_SHADER_DIR", root.c_str(), 1);
    RendererOptions options;
    options.validate = true;
    Renderer renderer(options);
    ::unsetenv("DEPTHSCOPE_SHADER_DIR");
    const scene::Scene scene = scene::load_scene("atrium", Settings{});
    renderer.set_scene(scene);
    const FrameResult before =
        renderer.render(scene.camera, Settings{}, {.width = 96, .height = 54});

    const fs::path shader = root / "forward.frag";
    std::string text;
    {
        std::ifstream in(shader);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::ofstream(shader) << text << "\nthis does not compile;\n";
    try {
        renderer.rebuild_pipelines();
        ADD_FAILURE() << "a broken shader must throw";
    } catch (const ds::shader::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("forward.frag:"), std::string::npos) << e.what();
    }
    const FrameResult during =
        renderer.render(scene.camera, Settings{}, {.width = 96, .height = 54});
    EXPECT_EQ(during.passes.size(), before.passes.size());
    EXPECT_EQ(during.covered_pixels, before.covered_pixels);

    std::ofstream(shader) << text;
    EXPECT_NO_THROW(renderer.rebuild_pipelines());
    const FrameResult after =
        renderer.render(scene.camera, Settings{}, {.width = 96, .height = 54});
    EXPECT_LT(differing_pixels(before, after, 8), size_t(96) * 54 / 100);
    EXPECT_EQ(renderer.validation_message_count(), 0u);
    fs::remove_all(root);
}

}  // namespace
