// Read-back as graph work on the real device: a read-back pass copies a graph image into a
// HostReadback buffer that the host reads by the image's handle after the fence; shader
// counters are zeroed by the host; roles and kinds show in the dump; transfer passes and
// in-pass dependencies refuse what does not fit. Validation (synchronization included) on.
#include <cstring>

#include "renderer/common/error.h"
#include "renderer/readback/host_readback.h"
#include "tests/unit/graph/graph_fixture.h"

namespace ds::graph::test {
namespace {

class GraphReadback : public GraphVk {
  protected:
    void SetUp() override {
        GraphVk::SetUp();
        readback_ = std::make_unique<HostReadback>(*context_);
    }
    void TearDown() override {
        context_->wait_idle();
        readback_.reset();
        retired_.flush();  // before the device goes, in GraphVk::TearDown
        GraphVk::TearDown();
    }
    // One frame; `declare` runs after the read-back's begin_frame.
    void run(VkExtent2D size, const std::function<void(RenderGraph&)>& declare) {
        frame(size, [&](RenderGraph& g) {
            readback_->begin_frame(retired_);
            declare(g);
        });
    }

    vk::DestroyList retired_;
    std::unique_ptr<HostReadback> readback_;
};

// "clear" fills an 8x4 image; "readback_image" (transfer, read-back role) copies it out.
ImageHandle clear_and_read_back(RenderGraph& g, HostReadback& readback, VkClearValue value) {
    ImageHandle image;
    add(
        g, "clear",
        [&](PassBuilder& b) {
            image = b.create_image("image", {.format = VK_FORMAT_R8G8B8A8_UNORM,
                                             .size = ImageSize::fixed(8, 4),
                                             .semantic = Semantic::LdrColor});
            clear_attachment(b, image, value, false);
        },
        nullptr);
    readback.add_copy_pass(g, "readback_image", {image});
    return image;
}

TEST_F(GraphReadback, ACopyPassReadsAnImageBackByItsHandle) {
    ImageHandle image;
    run({16, 16}, [&](RenderGraph& g) {
        image = clear_and_read_back(g, *readback_, colour(1.0f, 0.0f, 1.0f, 1.0f));
    });
    const std::span<const std::byte> bytes = readback_->image_bytes(image);
    ASSERT_EQ(bytes.size(), 8u * 4u * 4u);
    for (size_t i = 0; i < bytes.size(); i += 4) {
        EXPECT_EQ(uint8_t(bytes[i + 0]), 255u);
        EXPECT_EQ(uint8_t(bytes[i + 1]), 0u);
        EXPECT_EQ(uint8_t(bytes[i + 2]), 255u);
    }
    EXPECT_EQ(graph_->passes()[0].role, PassRole::Frame);
    EXPECT_EQ(graph_->passes()[1].role, PassRole::ReadBack);
    const std::string dump = graph_->dump();
    EXPECT_NE(dump.find("2. readback_image (transfer, readback)"), std::string::npos) << dump;
    EXPECT_NE(dump.find("barrier image: "), std::string::npos) << dump;
    EXPECT_NE(dump.find("readback_image: buffer 128 bytes"), std::string::npos) << dump;

    // The next frame forgets it until it is read back again; the buffer is reused.
    run({16, 16}, [&](RenderGraph& g) { (void)g; });
    EXPECT_TRUE(readback_->image_bytes(image).empty());
    run({16, 16}, [&](RenderGraph& g) {
        image = clear_and_read_back(g, *readback_, colour(0.0f, 1.0f, 0.0f, 1.0f));
    });
    EXPECT_EQ(uint8_t(readback_->image_bytes(image)[1]), 255u);

    // A released buffer is gone at once and made anew by the next copy.
    readback_->release("readback_image");
    EXPECT_TRUE(readback_->image_bytes(image).empty());
    run({16, 16}, [&](RenderGraph& g) {
        image = clear_and_read_back(g, *readback_, colour(0.0f, 0.0f, 1.0f, 1.0f));
    });
    EXPECT_EQ(uint8_t(readback_->image_bytes(image)[2]), 255u);
}

// A transfer pass fills part of a host storage buffer; the rest is the host's zeros.
TEST_F(GraphReadback, StorageBuffersStartZeroedByTheHost) {
    for (uint32_t fill_from : {0u, 8u}) {
        BufferHandle counters;
        run({16, 16}, [&](RenderGraph& g) {
            counters = readback_->import_storage(g, "counters", 16, 16);
            add(
                g, {"fill", PassKind::Transfer},
                [&](PassBuilder& b) { b.write(counters, Access::TransferDst); },
                [counters, fill_from](PassContext& ctx) {
                    vkCmdFillBuffer(ctx.cmd(), ctx.buffer(counters), fill_from, 16 - fill_from,
                                    0x11111111u);
                });
        });
        const std::span<const std::byte> bytes = readback_->buffer_bytes(counters);
        ASSERT_EQ(bytes.size(), 16u);
        uint32_t words[4];
        std::memcpy(words, bytes.data(), sizeof words);
        for (uint32_t i = 0; i < 4; ++i)
            EXPECT_EQ(words[i], 4 * i >= fill_from ? 0x11111111u : 0u) << fill_from << " " << i;
    }
}

TEST_F(GraphReadback, TransferPassesHaveNoAttachmentsOrShaders) {
    vk::DestroyList retired;
    graph_->begin_frame({16, 16}, retired);
    ImageHandle image;
    add(
        *graph_, "make",
        [&](PassBuilder& b) {
            image = b.create_image(
                "image", {.format = VK_FORMAT_R8G8B8A8_UNORM, .size = ImageSize::relative(1.0f)});
            b.color(image);
        },
        nullptr);
    auto transfer = [&](std::function<void(PassBuilder&)> setup) {
        add(*graph_, {"copy", PassKind::Transfer}, setup, nullptr);
    };
    expect_error([&] { transfer([&](PassBuilder& b) { b.color(image); }); },
                 "a transfer pass has no attachments");
    expect_error([&] { transfer([&](PassBuilder& b) { b.read(image, Access::Sampled); }); },
                 "a transfer pass runs no shader (sampled)");
}

TEST_F(GraphReadback, ADependencyNeedsBothAccessesDeclared) {
    vk::DestroyList retired;
    graph_->begin_frame({16, 16}, retired);
    ImageHandle image;
    add(
        *graph_, {"steps", PassKind::Compute},
        [&](PassBuilder& b) {
            image = b.create_image(
                "image", {.format = VK_FORMAT_R8G8B8A8_UNORM, .size = ImageSize::relative(1.0f)});
            b.write(image, Access::StorageWrite);
        },
        [&](PassContext& ctx) { ctx.dependency(image, Access::StorageWrite, Access::Sampled); });
    graph_->compile();
    expect_error([&] { context_->submit_once([&](VkCommandBuffer cmd) { graph_->execute(cmd); }); },
                 "pass 'steps', 'image': dependency() between accesses it did not declare");
}

}  // namespace
}  // namespace ds::graph::test
