#pragma once
// A validated context (synchronization validation included), a frame ring and a graph; frame()
// declares, compiles, executes, submits and waits for one frame.
#include <functional>
#include <memory>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/graph/graph.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/frame.h"
#include "renderer/vk/functions.h"

namespace ds::graph::test {

class GraphVk : public ::testing::Test {
  protected:
    void SetUp() override {
        vk::ContextOptions options;
        options.validate = true;
        context_ = std::make_unique<vk::Context>(options);
        frames_ = std::make_unique<vk::FrameRing>(*context_);
        graph_ = std::make_unique<RenderGraph>(*context_);
    }
    void TearDown() override {
        context_->wait_idle();
        graph_.reset();
        frames_.reset();
        EXPECT_EQ(context_->validation_message_count(), 0u);
        // The device's destruction too: the layer reports objects still alive there.
        const auto counter = context_->validation_counter();
        const uint64_t before = *counter;
        context_.reset();
        EXPECT_EQ(*counter, before) << "validation messages at device destruction";
    }

    // Runs one frame at `size` with the passes `declare` adds; returns the id for collect().
    uint64_t frame(VkExtent2D size, const std::function<void(RenderGraph&)>& declare) {
        vk::Frame& f = frames_->begin();
        graph_->begin_frame(size, f.retired);
        declare(*graph_);
        graph_->compile();
        const uint64_t id = graph_->execute(f.cmd);
        frames_->submit(f);
        frames_->wait(f);
        return id;
    }

    std::unique_ptr<vk::Context> context_;
    std::unique_ptr<vk::FrameRing> frames_;
    std::unique_ptr<RenderGraph> graph_;
};

// A pass without data of its own, through the graph's one add_pass form: `setup` declares,
// `record` records.
struct NoData {};
template <typename Setup, typename Record>
void add(RenderGraph& graph, const PassDecl& decl, Setup setup, Record record) {
    graph.add_pass<NoData>(
        decl, [&](PassBuilder& b, NoData&) { setup(b); },
        [record](PassContext& ctx, const NoData&) {
            if constexpr (!std::is_same_v<Record, std::nullptr_t>) record(ctx);
        });
}

// `target` declared cleared to `clear` (a colour or a depth attachment by its format).
inline void clear_attachment(PassBuilder& b, ImageHandle target, VkClearValue clear, bool depth) {
    if (depth)
        b.depth(target, {.load = Load::Clear, .clear = clear.depthStencil.depth});
    else
        b.color(target, {.load = Load::Clear, .clear = clear.color});
}

// The whole of a colour image into a tightly packed buffer.
inline void copy_to_buffer(const PassContext& ctx, ImageHandle image, BufferHandle buffer) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {ctx.extent(image).width, ctx.extent(image).height, 1};
    vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(image), ctx.layout(image), ctx.buffer(buffer), 1,
                           &region);
}

inline VkClearValue colour(float r, float g, float b, float a = 1.0f) {
    VkClearValue v{};
    v.color.float32[0] = r;
    v.color.float32[1] = g;
    v.color.float32[2] = b;
    v.color.float32[3] = a;
    return v;
}

// Runs `f`, which must throw a ds::Error whose message contains `fragment`.
template <typename F>
void expect_error(F&& f, const std::string& fragment) {
    try {
        f();
        ADD_FAILURE() << "expected ds::Error containing '" << fragment << "'";
    } catch (const ds::Error& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

}  // namespace ds::graph::test
