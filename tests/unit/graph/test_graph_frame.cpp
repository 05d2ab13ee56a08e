// A three-pass frame on the real device (lavapipe in CI) with validation and synchronization
// validation on: clear (colour attachment) -> swizzle (samples it, fullscreen triangle) ->
// readback (copy to a host buffer). Pixels, timings, counters and the dump are checked.
#include <cstring>
#include <sstream>

#include "renderer/vk/buffer.h"
#include "renderer/vk/image.h"
#include "tests/unit/graph/graph_fixture.h"
#include "tests/unit/graph/swizzle.h"

namespace ds::graph::test {
namespace {

constexpr VkFormat kFormat = kSwizzleFormat;
constexpr VkExtent2D kFrameSize{64, 48};

// The left half of the clear pass is red, the rest (0.25, 0.5, 0.75); swizzled: blue, and
// (0.75, 0.5, 0.25).
// The pass declares the target cleared to (0.25, 0.5, 0.75); this clears the left half red.
void clear_two_halves(const PassContext& ctx, ImageHandle target) {
    const VkExtent2D extent = ctx.extent(target);
    VkClearAttachment red{};
    red.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    red.colorAttachment = 0;
    red.clearValue = colour(1, 0, 0);
    const VkClearRect rect{{{0, 0}, {extent.width / 2, extent.height}}, 0, 1};
    vkCmdClearAttachments(ctx.cmd(), 1, &red, 1, &rect);
}

struct Targets {
    vk::Image result;     // imported: the swizzle pass renders into it
    vk::Buffer readback;  // imported: the readback pass copies the result into it
};

// Declares the three passes; `first` frame imports `result` from UNDEFINED, later ones from
// where the previous frame left it (TRANSFER_SRC_OPTIMAL after the copy).
void declare_frame(RenderGraph& graph, const Swizzle& swizzle, const Targets& t, bool first) {
    const ImageHandle result = graph.import_image(
        "result",
        {t.result.handle(), t.result.view(),
         ImageDesc{.format = kFormat,
                   .size = ImageSize::fixed(kFrameSize.width, kFrameSize.height),
                   .semantic = Semantic::LdrColor},
         first ? ExternalState{} : ExternalState::transfer_src(), ExternalState::transfer_src()});
    const BufferHandle readback = graph.import_buffer(
        "readback", {t.readback.handle(), t.readback.size(), {}, ExternalState::host_read()});

    struct Clear {
        ImageHandle colour;
    };
    const Clear& clear = graph.add_pass<Clear>(
        "clear",
        [](PassBuilder& b, Clear& d) {
            d.colour = b.create_image("colour", {.format = kFormat,
                                                 .size = ImageSize::relative(1.0f),
                                                 .semantic = Semantic::LdrColor});
            b.color(d.colour, {.load = Load::Clear, .clear = colour(0.25f, 0.5f, 0.75f).color});
        },
        [](PassContext& ctx, const Clear& d) { clear_two_halves(ctx, d.colour); });
    const ImageHandle source = clear.colour;
    add(
        graph, "swizzle",
        [&](PassBuilder& b) {
            b.read(source, Access::Sampled);
            b.color(result, {.load = Load::Clear, .clear = colour(0, 0, 0).color});
        },
        [&swizzle, source](PassContext& ctx) { swizzle.record(ctx, source); });
    add(
        graph, {"readback", PassKind::Transfer},
        [&](PassBuilder& b) {
            b.read(result, Access::TransferSrc);
            b.write(readback, Access::TransferDst);
        },
        [result, readback](PassContext& ctx) { copy_to_buffer(ctx, result, readback); });
}

uint32_t pixel(const vk::Buffer& buffer, uint32_t x, uint32_t y) {
    uint32_t value = 0;
    std::memcpy(&value, buffer.mapped() + (size_t(y) * kFrameSize.width + x) * 4, 4);
    return value;
}

bool near(uint32_t rgba, int r, int g, int b, int a) {
    const int expected[4] = {r, g, b, a};
    for (int c = 0; c < 4; ++c)
        if (std::abs(int((rgba >> (8 * c)) & 0xff) - expected[c]) > 1) return false;
    return true;
}

TEST_F(GraphVk, ThreePassesClearSampleReadBack) {
    const Swizzle swizzle(*context_);
    Targets t;
    t.result =
        vk::Image(*context_, {kFrameSize.width, kFrameSize.height, 1, kFormat,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_SAMPLE_COUNT_1_BIT, "result"});
    t.readback = vk::Buffer(
        *context_, {VkDeviceSize(kFrameSize.width) * kFrameSize.height * 4,
                    VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::Readback, "readback"});
    std::string second_dump;
    for (int f = 0; f < 3; ++f) {
        const uint64_t id =
            frame(kFrameSize, [&](RenderGraph& g) { declare_frame(g, swizzle, t, f == 0); });
        if (f == 1) second_dump = graph_->dump();
        t.readback.invalidate();
        size_t blue = 0, swizzled = 0;
        for (uint32_t y = 0; y < kFrameSize.height; ++y)
            for (uint32_t x = 0; x < kFrameSize.width; ++x) {
                const uint32_t p = pixel(t.readback, x, y);
                if (x < kFrameSize.width / 2)
                    blue += near(p, 0, 0, 255, 255);
                else
                    swizzled += near(p, 191, 128, 64, 255);
            }
        EXPECT_EQ(blue, size_t(kFrameSize.width / 2) * kFrameSize.height) << "frame " << f;
        EXPECT_EQ(swizzled, size_t(kFrameSize.width / 2) * kFrameSize.height) << "frame " << f;

        const std::vector<PassResult> results = graph_->collect(id);
        ASSERT_EQ(results.size(), 3u);
        EXPECT_EQ(results[0].name, "clear");
        EXPECT_EQ(results[1].name, "swizzle");
        EXPECT_EQ(results[2].name, "readback");
        if (graph_->has_timestamps()) {
            for (const PassResult& r : results) EXPECT_GE(r.gpu_ms, 0.0) << r.name;
            EXPECT_GT(results[1].gpu_ms, 0.0);
            EXPECT_LT(results[1].gpu_ms, 10000.0);
            // Starts from the frame's first timestamp, in recording order (one queue, one
            // command buffer: top-of-pipe timestamps do not run backwards).
            EXPECT_EQ(results[0].gpu_start_ms, 0.0);
            for (size_t i = 1; i < results.size(); ++i)
                EXPECT_GE(results[i].gpu_start_ms, results[i - 1].gpu_start_ms) << results[i].name;
        }
        if (graph_->has_statistics()) {
            EXPECT_GE(results[1].vertex_invocations, 3u);
            EXPECT_GE(results[1].clipping_primitives, 1u);
            EXPECT_GT(results[1].fragment_invocations, 0u);
            EXPECT_EQ(results[2].vertex_invocations, 0u) << "a copy draws nothing";
        }
    }
    EXPECT_TRUE(graph_->has_timestamps()) << "lavapipe has timestamps (DESIGN decision 2)";
    EXPECT_EQ(graph_->images_created(), 1u) << "one transient, created once for three frames";

    for (const char* expected :
         {"1. clear (graphics)", "2. swizzle (graphics)", "3. readback (transfer)",
          "colour: image R8G8B8A8_UNORM 64x48 (output x1) samples 1 mips 1 LdrColor transient",
          "result: image R8G8B8A8_UNORM 64x48 (fixed)", "external",
          "readback: buffer 12288 bytes external",
          "barrier colour: COLOR_ATTACHMENT_OPTIMAL -> SHADER_READ_ONLY_OPTIMAL",
          "barrier result: TRANSFER_SRC_OPTIMAL -> COLOR_ATTACHMENT_OPTIMAL",
          "barrier result: COLOR_ATTACHMENT_OPTIMAL -> TRANSFER_SRC_OPTIMAL",
          "barrier readback: buffer, COPY|BLIT|RESOLVE|CLEAR/TRANSFER_WRITE -> HOST/HOST_READ",
          "read colour: sampled (fragment) [SHADER_READ_ONLY_OPTIMAL]",
          // The graph begins each rendering: cleared, and stored for the pass that samples it.
          "renders 64x48: colour colour (clear, store)",
          "renders 64x48: colour result (clear, store)"})
        EXPECT_NE(second_dump.find(expected), std::string::npos) << expected << "\n" << second_dump;
    std::ostringstream streamed;
    streamed << *graph_;
    EXPECT_EQ(streamed.str(), graph_->dump());
    std::printf("%s", second_dump.c_str());
    EXPECT_EQ(context_->validation_message_count(), 0u);
}

}  // namespace
}  // namespace ds::graph::test
