#include "tests/gpu/screen_space/gpu_rig.h"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/packing.hpp>

#include "renderer/common/error.h"
#include "renderer/vk/barrier.h"
#include "renderer/vk/check.h"

namespace ds::test {
namespace {

using graph::Access;

uint32_t texel_size(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8_UNORM:
            return 1;
        case VK_FORMAT_R16_SFLOAT:
            return 2;
        case VK_FORMAT_R16G16_SFLOAT:
            return 4;
        case VK_FORMAT_R16G16B16A16_SFLOAT:  // packed AO: r, g read back (AO, distance)
            return 8;
        default:
            throw Error("read-back of format " + std::to_string(int(format)) + " not supported");
    }
}

HostImage decode(VkFormat format, VkExtent2D extent, const std::byte* data) {
    HostImage img;
    img.width = extent.width;
    img.height = extent.height;
    const size_t n = size_t(extent.width) * extent.height;
    img.r.resize(n);
    if (format != VK_FORMAT_R8_UNORM && format != VK_FORMAT_R16_SFLOAT) img.g.resize(n);
    for (size_t i = 0; i < n; ++i) {
        if (format == VK_FORMAT_R8_UNORM) {
            img.r[i] = float(uint8_t(data[i])) / 255.0f;
        } else {
            uint16_t h[4] = {0, 0, 0, 0};
            std::memcpy(h, data + i * texel_size(format), texel_size(format));
            img.r[i] = glm::unpackHalf1x16(h[0]);
            if (!img.g.empty()) img.g[i] = glm::unpackHalf1x16(h[1]);
        }
    }
    return img;
}

// Copies `data` into `image` (TRANSFER_DST) and leaves it SHADER_READ_ONLY_OPTIMAL.
void upload_image(vk::Context& context, const vk::Image& image, const void* data, size_t size) {
    vk::Buffer staging(
        context, {size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUsage::Upload, "staging"});
    staging.write(data, size);
    const VkImageAspectFlags aspect = image.aspect();
    context.submit_once([&](VkCommandBuffer cmd) {
        vk::image_barrier(cmd, {.image = image.handle(),
                                .aspect = aspect,
                                .old_layout = VK_IMAGE_LAYOUT_UNDEFINED,
                                .new_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                .dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                                .dst_access = VK_ACCESS_2_TRANSFER_WRITE_BIT});
        VkBufferImageCopy region{};
        region.imageSubresource = {aspect, 0, 0, 1};
        region.imageExtent = {image.width(), image.height(), 1};
        vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        vk::image_barrier(cmd, {.image = image.handle(),
                                .aspect = aspect,
                                .old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                .new_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                .src_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                                .src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                .dst_stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                .dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    });
}

// Uploaded before the frame and fenced: sampled-ready, nothing left to wait for.
graph::ExternalImage sampled_input(const vk::Image& image, graph::Semantic semantic) {
    return {image.handle(),
            image.view(),
            {.format = image.format(),
             .size = graph::ImageSize::fixed(image.width(), image.height()),
             .semantic = semantic},
            {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE},
            std::nullopt};
}

}  // namespace

glm::ivec2 ao_source_pixel(glm::ivec2 q, glm::ivec2 size, glm::ivec2 full) {
    const glm::vec2 p = (glm::vec2(q) + 0.5f) * glm::vec2(full) / glm::vec2(size);
    return glm::min(glm::ivec2(p), full - 1);
}

glm::vec2 oct_encode(glm::vec3 n) {
    n /= std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    glm::vec2 p(n.x, n.y);
    if (n.z < 0.0f)
        p = (1.0f - glm::abs(glm::vec2(p.y, p.x))) *
            glm::vec2(p.x >= 0.0f ? 1.0f : -1.0f, p.y >= 0.0f ? 1.0f : -1.0f);
    return p;
}

void write_png(const std::string& path, const HostImage& image) {
    std::vector<uint8_t> bytes(image.r.size());
    for (size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = uint8_t(std::lround(std::clamp(image.r[i], 0.0f, 1.0f) * 255.0f));
    stbi_write_png(path.c_str(), int(image.width), int(image.height), 1, bytes.data(),
                   int(image.width));
}

GpuRig& GpuRig::get() {
    static GpuRig rig;
    return rig;
}

GpuRig::GpuRig() {
    vk::ContextOptions options;
    options.validate = true;
    context_ = std::make_unique<vk::Context>(options);
    // No disk cache: the tests compile what is in the tree, every time.
    compiler_ = std::make_unique<shader::Compiler>(shader::Compiler::default_shader_root(),
                                                   std::filesystem::path());
    readback_ = std::make_unique<HostReadback>(*context_);
    const VkDescriptorSetLayoutBinding binding = vk::layout_binding(
        0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT);
    frame_layout_ = vk::DescriptorSetLayout(*context_, std::span(&binding, 1), "test frame set");
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1};
    frame_pool_ = vk::DescriptorPool(*context_, 1, std::span(&size, 1), "test frame pool");
    frame_set_ = frame_pool_.allocate(frame_layout_.handle());
    uniform_buffer_ =
        vk::Buffer(*context_, {sizeof(passes::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                               vk::MemoryUsage::Upload, "frame uniforms"});
    vk::DescriptorWriter()
        .buffer(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uniform_buffer_.handle())
        .update(context_->device(), frame_set_);
}

passes::PassServices GpuRig::services() {
    return {*context_,      *compiler_,           frame_layout_.handle(),
            VK_NULL_HANDLE, VK_FORMAT_D32_SFLOAT, *readback_};
}

void GpuRig::upload(const SyntheticFrame& frame) {
    context_->wait_idle();
    const uint32_t w = frame.width, h = frame.height;
    depth_ = vk::Image(*context_, {w, h, 1, VK_FORMAT_D32_SFLOAT,
                                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                   VK_SAMPLE_COUNT_1_BIT, "synthetic depth"});
    normals_ = vk::Image(*context_, {w, h, 1, VK_FORMAT_A2B10G10R10_UNORM_PACK32,
                                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     VK_SAMPLE_COUNT_1_BIT, "synthetic normals"});
    upload_image(*context_, depth_, frame.depth.data(), frame.depth.size() * sizeof(float));
    upload_image(*context_, normals_, frame.normals.data(),
                 frame.normals.size() * sizeof(uint32_t));
    reverse_z_ = frame.reverse_z;
    set_uniforms(frame.uniforms);
}

void GpuRig::set_uniforms(const passes::FrameUniforms& uniforms) {
    uniforms_ = uniforms;
}

vk::Image GpuRig::make_packed_ao(const SyntheticFrame& frame, uint32_t width, uint32_t height,
                                 const std::vector<float>& values) {
    vk::Image image(*context_, {width, height, 1, VK_FORMAT_R16G16B16A16_SFLOAT,
                                VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                VK_SAMPLE_COUNT_1_BIT, "test packed AO input"});
    std::vector<uint16_t> halves(values.size() * 4);
    const glm::ivec2 full{int(frame.width), int(frame.height)};
    const glm::mat4& view = frame.uniforms.view;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const glm::ivec2 s = ao_source_pixel({int(x), int(y)}, {int(width), int(height)}, full);
            const PixelHit& hit = frame.hit(uint32_t(s.x), uint32_t(s.y));
            const size_t i = size_t(y) * width + x;
            glm::vec4 texel(1.0f, 0.0f, 0.0f, 0.0f);  // sky
            if (hit.surface != Surface::Sky) {
                const float distance = -(view * glm::vec4(hit.position, 1.0f)).z;
                const glm::vec3 n = glm::normalize(glm::mat3(view) * hit.normal);
                texel = {values[i], distance, oct_encode(n)};
            }
            for (int c = 0; c < 4; ++c) halves[i * 4 + size_t(c)] = glm::packHalf1x16(texel[c]);
        }
    upload_image(*context_, image, halves.data(), halves.size() * sizeof(uint16_t));
    return image;
}

graph::ImageHandle GpuRig::import_input(graph::RenderGraph& graph, const std::string& name,
                                        const vk::Image& image) const {
    return graph.import_image(name, sampled_input(image, graph::Semantic::AO));
}

// One read-back pass (transfer, read-back role) copying every named image to the host.
std::vector<graph::ImageHandle> GpuRig::add_read_back(graph::RenderGraph& graph,
                                                      const std::vector<std::string>& names) {
    readback_->begin_frame(retired_);
    std::vector<graph::ImageHandle> images;
    for (const std::string& name : names) {
        images.push_back(graph.find_image(name));
        if (!images.back().valid()) throw Error("read-back: no image '" + name + "' in the graph");
    }
    if (images.empty()) return images;
    readback_->add_copy_pass(graph, "readback", images);
    return images;
}

FrameOutput GpuRig::run_frame(graph::RenderGraph& graph, const Declare& declare,
                              const std::vector<std::string>& read_back,
                              const passes::FrameOptions& options) {
    uniforms_.flags.y = uint32_t(frame_number_);
    uniform_buffer_.write(&uniforms_, sizeof(uniforms_));

    graph.begin_frame({depth_.width(), depth_.height()}, retired_);
    passes::FrameResources res;
    res.frame_uniforms = graph.import_buffer(
        "frame_uniforms",
        {uniform_buffer_.handle(),
         sizeof(passes::FrameUniforms),
         {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_WRITE_BIT},
         std::nullopt});
    res.depth = graph.import_image(
        "depth", sampled_input(depth_, reverse_z_ ? graph::Semantic::ReverseZDepth
                                                  : graph::Semantic::ForwardZDepth));
    res.normals =
        graph.import_image("normals", sampled_input(normals_, graph::Semantic::EncodedNormal));
    passes::FrameInputs in;
    in.frame_set = frame_set_;
    in.options = options;
    in.frame_number = frame_number_;
    declare(graph, in, res);

    const std::vector<graph::ImageHandle> images = add_read_back(graph, read_back);
    graph.compile();
    uint64_t id = 0;
    context_->submit_once([&](VkCommandBuffer cmd) { id = graph.execute(cmd); });
    retired_.flush();  // submit_once waited: nothing retired is in use
    ++frame_number_;

    FrameOutput out;
    out.passes = graph.collect(id);
    for (size_t i = 0; i < images.size(); ++i) {
        const graph::ResourceInfo& info = graph.resources()[images[i].index];
        out.images[read_back[i]] =
            decode(info.image.format, info.extent, readback_->image_bytes(images[i]).data());
    }
    return out;
}

}  // namespace ds::test
