// Graph-owned resources on the real device: the image cache (a frame allocates nothing, a
// resize recreates relative images only), history ping-pong and its validity, and the errors
// a wrong declaration gets.
#include <cstring>

#include "renderer/common/error.h"
#include "renderer/vk/buffer.h"
#include "tests/unit/graph/graph_fixture.h"

namespace ds::graph::test {
namespace {

// A pass that clears `name` (created with `desc`) and nothing else.
ImageHandle add_clear(RenderGraph& graph, const std::string& name, const ImageDesc& desc) {
    ImageHandle image;
    const bool depth = desc.format == VK_FORMAT_D32_SFLOAT;
    add(
        graph, "clear " + name,
        [&](PassBuilder& b) {
            image = b.create_image(name, desc);
            VkClearValue clear = colour(0, 0, 0);
            if (depth) clear.depthStencil = {0.0f, 0};
            clear_attachment(b, image, clear, depth);
        },
        nullptr);
    return image;
}

struct Sizes {
    ImageHandle full, half, shadow;
};

Sizes declare_sizes(RenderGraph& graph) {
    return {
        add_clear(graph, "full",
                  {.format = VK_FORMAT_R8G8B8A8_UNORM, .size = ImageSize::relative(1.0f)}),
        add_clear(graph, "half", {.format = VK_FORMAT_R8_UNORM, .size = ImageSize::relative(0.5f)}),
        add_clear(graph, "shadow",
                  {.format = VK_FORMAT_D32_SFLOAT,
                   .size = ImageSize::fixed(256, 256),
                   .semantic = Semantic::ShadowDepth})};
}

VkExtent2D extent_of(const RenderGraph& graph, ImageHandle h) {
    return graph.resources()[h.index].extent;
}

TEST_F(GraphVk, ResizeRecreatesRelativeImagesOnly) {
    Sizes s;
    frame({64, 48}, [&](RenderGraph& g) { s = declare_sizes(g); });
    const VkImage full = graph_->image(s.full), half = graph_->image(s.half),
                  shadow = graph_->image(s.shadow);
    EXPECT_EQ(graph_->images_created(), 3u);
    EXPECT_EQ(extent_of(*graph_, s.half).width, 32u);

    frame({64, 48}, [&](RenderGraph& g) { s = declare_sizes(g); });
    EXPECT_EQ(graph_->images_created(), 3u) << "the same frame again allocates nothing";
    EXPECT_EQ(graph_->image(s.full), full);
    EXPECT_EQ(graph_->image(s.half), half);

    frame({80, 60}, [&](RenderGraph& g) { s = declare_sizes(g); });
    EXPECT_EQ(graph_->images_created(), 5u) << "two relative images recreated";
    EXPECT_NE(graph_->image(s.full), full);
    EXPECT_NE(graph_->image(s.half), half);
    EXPECT_EQ(graph_->image(s.shadow), shadow) << "an absolute size does not follow the output";
    EXPECT_EQ(extent_of(*graph_, s.full).width, 80u);
    EXPECT_EQ(extent_of(*graph_, s.full).height, 60u);
    EXPECT_EQ(extent_of(*graph_, s.half).width, 40u);
    EXPECT_EQ(extent_of(*graph_, s.half).height, 30u);
    EXPECT_EQ(extent_of(*graph_, s.shadow).width, 256u);
    EXPECT_NE(graph_->dump().find("half: image R8_UNORM 40x30 (output x0.5)"), std::string::npos)
        << graph_->dump();
    EXPECT_NE(graph_->dump().find("shadow: image D32_SFLOAT 256x256 (fixed)"), std::string::npos);
    EXPECT_NE(graph_->dump().find("ShadowDepth"), std::string::npos);
}

// Frame k clears history.current to (k + 1) * 20 and copies pixel (0, 0) of history.previous
// into `readback`; the record lambda reports whether the history was valid.
struct HistoryFrame {
    bool valid = false;
    uint8_t previous = 0;
};

HistoryFrame run_history_frame(
    GraphVk& test,
    const std::function<uint64_t(VkExtent2D, const std::function<void(RenderGraph&)>&)>& frame,
    VkExtent2D size, uint32_t k, vk::Buffer& readback) {
    (void)test;
    HistoryFrame out;
    frame(size, [&](RenderGraph& g) {
        const BufferHandle rb = g.import_buffer(
            "readback", {readback.handle(), readback.size(), {}, ExternalState::host_read()});
        HistoryImage history;
        struct Peek {
            HistoryImage history;
        };
        const Peek& peek = g.add_pass<Peek>(
            {"peek", PassKind::Transfer},
            [&](PassBuilder& b, Peek& d) {
                d.history = b.create_history("accum", {.format = VK_FORMAT_R8G8B8A8_UNORM,
                                                       .size = ImageSize::relative(1.0f),
                                                       .semantic = Semantic::AO});
                b.read(d.history.previous, Access::TransferSrc);
                b.write(rb, Access::TransferDst);
            },
            [&out, rb](PassContext& ctx, const Peek& d) {
                out.valid = ctx.history_valid(d.history);
                VkBufferImageCopy region{};
                region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
                region.imageExtent = {1, 1, 1};
                vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(d.history.previous),
                                       ctx.layout(d.history.previous), ctx.buffer(rb), 1, &region);
            });
        const ImageHandle current = peek.history.current;
        add(
            g, "accumulate",
            [&](PassBuilder& b) {
                clear_attachment(b, current, colour(float((k + 1) * 20) / 255.0f, 0, 0), false);
            },
            nullptr);
    });
    readback.invalidate();
    out.previous = uint8_t(readback.mapped()[0]);
    return out;
}

TEST_F(GraphVk, HistoryPingPongsAndResetsOnCutAndResize) {
    vk::Buffer readback(*context_, {4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::Readback,
                                    "history readback"});
    auto run = [&](VkExtent2D size, uint32_t k) {
        return run_history_frame(
            *this, [&](VkExtent2D s, const auto& d) { return frame(s, d); }, size, k, readback);
    };
    EXPECT_FALSE(run({32, 32}, 0).valid) << "nothing written yet";
    HistoryFrame f = run({32, 32}, 1);
    EXPECT_TRUE(f.valid);
    EXPECT_EQ(f.previous, 20) << "frame 0's current is frame 1's previous";
    f = run({32, 32}, 2);
    EXPECT_TRUE(f.valid);
    EXPECT_EQ(f.previous, 40);
    EXPECT_NE(
        graph_->dump().find("accum.previous: image R8G8B8A8_UNORM 32x32 (output x1) samples 1 "
                            "mips 1 AO history previous (valid)"),
        std::string::npos)
        << graph_->dump();

    graph_->invalidate_history();  // a camera cut
    EXPECT_FALSE(run({32, 32}, 3).valid);
    f = run({32, 32}, 4);
    EXPECT_TRUE(f.valid);
    EXPECT_EQ(f.previous, 80);

    EXPECT_FALSE(run({48, 32}, 5).valid) << "a resize loses the history";
    f = run({48, 32}, 6);
    EXPECT_TRUE(f.valid);
    EXPECT_EQ(f.previous, 120);
    EXPECT_EQ(graph_->images_created(), 4u) << "one pair, recreated once on resize";
}

TEST_F(GraphVk, WrongDeclarationsAreClearErrors) {
    vk::DestroyList retired;
    expect_error(
        [&] {
            add(
                *graph_, "early", [](PassBuilder&) {}, nullptr);
        },
        "begin_frame");
    graph_->begin_frame({16, 16}, retired);
    ImageHandle colour_image, depth_image;
    BufferHandle buffer;
    add(
        *graph_, "make",
        [&](PassBuilder& b) {
            colour_image = b.create_image(
                "colour", {.format = VK_FORMAT_R8G8B8A8_UNORM, .size = ImageSize::relative(1.0f)});
            depth_image = b.create_image(
                "depth", {.format = VK_FORMAT_D32_SFLOAT, .size = ImageSize::relative(1.0f)});
            buffer = b.create_buffer("counts", {.size = 64});
            b.color(colour_image);
        },
        nullptr);
    auto in_pass = [&](std::function<void(PassBuilder&)> setup,
                       PassKind kind = PassKind::Graphics) {
        add(*graph_, {"bad", kind}, setup, nullptr);
    };
    expect_error([&] { in_pass([&](PassBuilder& b) { b.write(colour_image, Access::Sampled); }); },
                 "pass 'bad', 'colour': sampled is not a write");
    expect_error(
        [&] { in_pass([&](PassBuilder& b) { b.read(colour_image, Access::ColorAttachment); }); },
        "colour attachment is an attachment: declare it with color()");
    expect_error(
        [&] { in_pass([&](PassBuilder& b) { b.read(colour_image, Access::VertexRead); }); },
        "vertex input does not apply to an image");
    expect_error([&] { in_pass([&](PassBuilder& b) { b.read(buffer, Access::Sampled); }); },
                 "sampled does not apply to a buffer");
    expect_error([&] { in_pass([&](PassBuilder& b) { b.depth(colour_image); }); },
                 "does not fit format R8G8B8A8_UNORM");
    expect_error([&] { in_pass([&](PassBuilder& b) { b.color(depth_image); }); },
                 "does not fit format D32_SFLOAT");
    expect_error(
        [&] { in_pass([&](PassBuilder& b) { b.color(colour_image); }, PassKind::Compute); },
        "a compute pass has no attachments");
    expect_error(
        [&] {
            in_pass([&](PassBuilder& b) { b.render_area({16, 16}); }, PassKind::Transfer);
        },
        "a transfer pass renders nothing");
    expect_error(
        [&] {
            in_pass([&](PassBuilder& b) {
                b.depth(depth_image);
                b.depth(depth_image, {.read_only = true});
            });
        },
        "declares a second depth attachment");
    expect_error(
        [&] {
            in_pass([&](PassBuilder& b) {
                b.create_image("colour",
                               {.format = VK_FORMAT_R8_UNORM, .size = ImageSize::relative(1)});
            });
        },
        "resource 'colour' declared twice");
    expect_error([&] { graph_->execute(VK_NULL_HANDLE); }, "compile() first");
}

TEST_F(GraphVk, RecordingAnUndeclaredResourceThrows) {
    vk::DestroyList retired;
    graph_->begin_frame({16, 16}, retired);
    ImageHandle a, b;
    add(
        *graph_, "make",
        [&](PassBuilder& pb) {
            a = pb.create_image(
                "a", {.format = VK_FORMAT_R8G8B8A8_UNORM, .size = ImageSize::relative(1.0f)});
            b = pb.create_image(
                "b", {.format = VK_FORMAT_R8G8B8A8_UNORM, .size = ImageSize::relative(1.0f)});
            pb.color(a, {.load = Load::Clear});
            pb.color(b, {.load = Load::Clear});
        },
        nullptr);
    add(
        *graph_, {"sneaky", PassKind::Compute},
        [&](PassBuilder& pb) { pb.read(a, Access::Sampled); },
        [&](PassContext& ctx) { (void)ctx.view(b); });
    graph_->compile();
    expect_error([&] { context_->submit_once([&](VkCommandBuffer cmd) { graph_->execute(cmd); }); },
                 "pass 'sneaky' did not declare 'b'");
}

}  // namespace
}  // namespace ds::graph::test
