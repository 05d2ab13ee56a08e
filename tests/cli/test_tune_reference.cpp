// The reference's host side in-process on the device: its tonemap (shaders/tonemap.frag on the
// host) gives the GPU's final image from the GPU's HDR image, and a reference is the same twice.
#include <gtest/gtest.h>

#include <cstdlib>

#include "capture/tune/reference.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"

namespace {

using namespace ds;

TEST(TuneReference, HostTonemapIsTheGpusAndTheReferenceRepeats) {
    RendererOptions options;
    options.validate = true;
    Renderer renderer(options);
    const scene::Scene scene = scene::load_scene("edges", Settings{});
    renderer.set_scene(scene);
    Settings settings = tune::scored_settings(Settings{});
    settings.set("exposure", "1.7");
    RenderRequest request{.width = 96, .height = 54, .read_back = ReadBack::Color};
    request.inspect = {{"hdr"}};
    const FrameResult f = renderer.render(scene.camera, settings, request);
    const InspectedImage* hdr = f.image("hdr");
    ASSERT_NE(hdr, nullptr);
    int worst = 0;
    for (size_t p = 0; p < size_t(f.width) * f.height; ++p) {
        uint8_t host[4];
        tune::tonemap_rgba8(&hdr->texels[p * 4], 1.7f, host);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(host[c] - f.rgba8[p * 4 + c]));
    }
    EXPECT_LE(worst, 1);  // the hardware's sRGB encoding may round the other way
    const tune::Reference a =
        tune::render_reference(renderer, scene, scene.camera, settings, {96, 54});
    const tune::Reference b =
        tune::render_reference(renderer, scene, scene.camera, settings, {96, 54});
    EXPECT_EQ(a.rgba8, b.rgba8);
    EXPECT_EQ(a.edges, b.edges);
    EXPECT_GT(std::count(a.edges.begin(), a.edges.end(), 1), 0);
    renderer.shutdown();
    EXPECT_EQ(renderer.validation_message_count(), 0u);
}

}  // namespace
