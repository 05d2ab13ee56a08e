// The survival shader (layer/spirv/survival.h) and the vertex shader's instance output
// (instance_output.h) on the device (lavapipe here), validation on: an attachment-less pass over
// 8 x 4 pixels draws two instances of a full-screen triangle at depths one float ULP apart
// (instance 0 at 0.5, instance 1 just behind), with an application fragment shader that
// discards the columns x < 2. Each ZPixels mode in turn; the buffers read back.
#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "instrument_test_fixture.h"
#include "layer/spirv/instance_output.h"
#include "layer/spirv/survival.h"
#include "renderer/vk/barrier.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/context.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/functions.h"
#include "renderer/vk/pipeline.h"

namespace ds::layer {
namespace {

constexpr uint32_t kWidth = 8, kHeight = 4, kPixels = kWidth * kHeight, kDrawId = 42;
constexpr uint32_t kHalf = 0x3F000000;  // 0.5f: instance 0's depth; instance 1: kHalf + 1
constexpr uint32_t kSurvivors = (kWidth - 2) * kHeight;
constexpr uint32_t kBits32 = 32u << 16, kBits24 = 24u << 16;

constexpr const char* kVertexShader = R"(#version 460
layout(location = 0) out vec2 uv;
void main() {
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    uv = p;
    float z = uintBitsToFloat(floatBitsToUint(0.5) + uint(gl_InstanceIndex));
    gl_Position = vec4(p * 2.0 - 1.0, z, 1.0);
}
)";

class SurvivalRenderTest : public testing::InstrumentTest {
  protected:
    void SetUp() override;
    void TearDown() override {
        if (context_) {
            EXPECT_EQ(context_->validation_message_count(), 0u);
        }
    }
    // One pass with ZPixels.mode `mode` and params `params`; Records.capacity `capacity`, the
    // records cleared.
    void draw(uint32_t mode, uint32_t params, uint32_t capacity = 100);
    // Every pixel's nearest word set to `nearest`, its EQUAL count to 0.
    void reset_pixels(uint32_t nearest) {
        std::vector<uint32_t> words(2 * kPixels, 0);
        for (uint32_t p = 0; p < kPixels; ++p) words[2 * p] = nearest;
        zpixels_.write(words.data(), words.size() * 4, 16);
    }
    uint32_t* zpixels() const { return words(zpixels_); }
    uint32_t* records() const { return words(records_); }
    static uint32_t* words(const vk::Buffer& b) {
        b.invalidate();
        return reinterpret_cast<uint32_t*>(b.mapped());
    }
    // The records 1..n as (pixel, draw, instance, depth bits).
    std::multiset<std::vector<uint32_t>> read_records(uint32_t n) const {
        std::multiset<std::vector<uint32_t>> out;
        const uint32_t* w = records();
        for (uint32_t r = 1; r <= n; ++r) out.insert({w + 4 + 4 * r, w + 8 + 4 * r});
        return out;
    }

    std::unique_ptr<vk::Context> context_;
    vk::Buffer draw_, zpixels_, records_;
    vk::DescriptorSetLayout set_layout_;
    vk::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    vk::PipelineLayout layout_;
    vk::Pipeline pipeline_;
};

vk::Buffer storage(vk::Context& c, size_t bytes) {
    return vk::Buffer(c, {.size = bytes,
                          .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                          .memory = vk::MemoryUsage::Readback,
                          .name = "survival test"});
}

void SurvivalRenderTest::SetUp() {
    InstrumentTest::SetUp();
    vk::ContextOptions options;
    options.validate = true;
    context_ = std::make_unique<vk::Context>(options);
    vk::Context& c = *context_;
    draw_ = storage(c, 16);
    zpixels_ = storage(c, 16 + 8 * kPixels);
    records_ = storage(c, 16 + 16 * 1001);
    const uint32_t draw_counters[4] = {0, 0, 0, kDrawId};
    draw_.write(draw_counters, sizeof(draw_counters));

    const SurvivalBindings b{.set = 0};
    const VkDescriptorSetLayoutBinding bindings[] = {
        vk::layout_binding(b.draw_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           VK_SHADER_STAGE_FRAGMENT_BIT),
        vk::layout_binding(b.zpixel_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           VK_SHADER_STAGE_FRAGMENT_BIT),
        vk::layout_binding(b.record_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           VK_SHADER_STAGE_FRAGMENT_BIT)};
    set_layout_ = vk::DescriptorSetLayout(c, bindings);
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3}};
    pool_ = vk::DescriptorPool(c, 1, sizes);
    set_ = pool_.allocate(set_layout_.handle());
    vk::DescriptorWriter()
        .buffer(b.draw_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, draw_.handle())
        .buffer(b.zpixel_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, zpixels_.handle())
        .buffer(b.record_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, records_.handle())
        .update(c.device(), set_);
    const VkDescriptorSetLayout sets[] = {set_layout_.handle()};
    layout_ = vk::PipelineLayout(c, sets);

    const InstanceOutput vs =
        add_instance_output(compile(kVertexShader, shader::Stage::Vertex), "main");
    ASSERT_EQ(vs.location, 1u);
    const std::vector<uint32_t> fs =
        survival_fragment(compile(fragment("", "if (gl_FragCoord.x < 2.0) discard;")), "main", b,
                          {.instance_location = vs.location});
    pipeline_ = vk::GraphicsPipelineBuilder()
                    .shader(VK_SHADER_STAGE_VERTEX_BIT, vs.spirv)
                    .shader(VK_SHADER_STAGE_FRAGMENT_BIT, fs)
                    .layout(layout_.handle())
                    .build(c, "survival test");
}

void SurvivalRenderTest::draw(uint32_t mode, uint32_t params, uint32_t capacity) {
    const uint32_t header[4] = {kWidth, kHeight, params, mode};
    zpixels_.write(header, sizeof(header));
    std::vector<uint32_t> record_words(records_.size() / 4, 0);
    record_words[1] = capacity;
    records_.write(record_words.data(), record_words.size() * 4);
    context_->submit_once([&](VkCommandBuffer cmd) {
        VkRenderingInfo rendering{};
        rendering.sType = VK_STRUCTURE_TYPE_RENDERING_INFO;
        rendering.renderArea = {{0, 0}, {kWidth, kHeight}};
        rendering.layerCount = 1;
        vk::fn().cmd_begin_rendering(cmd, &rendering);
        const VkViewport viewport{0, 0, float(kWidth), float(kHeight), 0, 1};
        const VkRect2D scissor{{0, 0}, {kWidth, kHeight}};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vk::fn().cmd_set_cull_mode(cmd, VK_CULL_MODE_NONE);
        vk::fn().cmd_set_depth_test_enable(cmd, VK_FALSE);
        vk::fn().cmd_set_depth_write_enable(cmd, VK_FALSE);
        vk::fn().cmd_set_depth_compare_op(cmd, VK_COMPARE_OP_ALWAYS);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.handle());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.handle(), 0, 1, &set_,
                                0, nullptr);
        vkCmdDraw(cmd, 3, 2, 0, 0);
        vk::fn().cmd_end_rendering(cmd);
        vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                           VK_ACCESS_2_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                           VK_ACCESS_2_HOST_READ_BIT);
    });
}

TEST_F(SurvivalRenderTest, NearestAndEqualCounts) {
    reset_pixels(0xFFFFFFFF);
    draw(1, kBits32);
    for (uint32_t p = 0; p < kPixels; ++p)
        EXPECT_EQ(zpixels()[4 + 2 * p], p % kWidth < 2 ? 0xFFFFFFFF : kHalf) << p;
    reset_pixels(0);
    draw(2, kBits32);  // reverse depth: the farther instance
    for (uint32_t p = 0; p < kPixels; ++p)
        EXPECT_EQ(zpixels()[4 + 2 * p], p % kWidth < 2 ? 0 : kHalf + 1) << p;
    reset_pixels(kHalf);
    draw(4, kBits32);
    for (uint32_t p = 0; p < kPixels; ++p) {
        EXPECT_EQ(zpixels()[4 + 2 * p + 1], p % kWidth < 2 ? 0u : 2u) << p;
        EXPECT_EQ(zpixels()[4 + 2 * p], kHalf) << p;  // untouched in mode 4
    }
    EXPECT_EQ(records()[0], 0u);  // no records outside mode 3
}

// The records expected: every surviving pixel, the instances up to `last_instance`.
std::multiset<std::vector<uint32_t>> expected_records(uint32_t last_instance) {
    std::multiset<std::vector<uint32_t>> out;
    for (uint32_t p = 0; p < kPixels; ++p)
        for (uint32_t i = 0; i <= last_instance && p % kWidth >= 2; ++i)
            out.insert({p, kDrawId, i, kHalf + i});
    return out;
}

TEST_F(SurvivalRenderTest, RecordsWithinMaxSteps) {
    reset_pixels(kHalf);   // as mode 1 leaves it
    draw(3, kBits32 | 1);  // one ULP: both instances
    EXPECT_EQ(records()[0], 2 * kSurvivors);
    EXPECT_EQ(read_records(2 * kSurvivors), expected_records(1));
    draw(3, kBits32 | 0);  // the nearest only
    EXPECT_EQ(records()[0], kSurvivors);
    EXPECT_EQ(read_records(kSurvivors), expected_records(0));
    draw(3, kBits24 | 0);  // one float ULP is no 24-bit unorm step
    EXPECT_EQ(records()[0], 2 * kSurvivors);
    EXPECT_EQ(read_records(2 * kSurvivors), expected_records(1));
    reset_pixels(0xFFFFFFFF);  // nothing recorded: no unorm step is near
    draw(3, kBits24 | 0xFFFF);
    EXPECT_EQ(records()[0], 0u);
}

TEST_F(SurvivalRenderTest, RecordsBeyondCapacityAreCountedNotWritten) {
    reset_pixels(kHalf);
    draw(3, kBits32 | 1, 10);
    EXPECT_EQ(records()[0], 2 * kSurvivors);
    for (uint32_t r = 1; r <= 10; ++r) EXPECT_EQ(records()[4 + 4 * r + 1], kDrawId) << r;
    for (uint32_t r = 11; r <= 2 * kSurvivors; ++r) EXPECT_EQ(records()[4 + 4 * r + 1], 0u) << r;
}

}  // namespace
}  // namespace ds::layer
