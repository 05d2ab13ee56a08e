#include "renderer/graph/access.h"

namespace ds::graph {
namespace {

constexpr VkPipelineStageFlags2 kDepthTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
constexpr VkPipelineStageFlags2 kTransfer =
    VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_RESOLVE_BIT;

VkPipelineStageFlags2 shader_stages(Shader shader) {
    if (shader == Shader::Default) return VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    VkPipelineStageFlags2 stages = 0;
    if (has(shader, Shader::Vertex)) stages |= VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
    if (has(shader, Shader::Fragment)) stages |= VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    if (has(shader, Shader::Compute)) stages |= VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    return stages;
}

}  // namespace

Use describe(Access access, Shader shader, bool depth) {
    const VkPipelineStageFlags2 in_shader = shader_stages(shader);
    switch (access) {
        case Access::ColorAttachment:
            return {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
        // DEPTH_STENCIL_* layouts rather than DEPTH_*: the latter need the
        // separateDepthStencilLayouts feature, and these are valid for depth-only formats too.
        case Access::DepthAttachment:
            return {VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, kDepthTests,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
        case Access::DepthReadOnly:
            return {VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, kDepthTests,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT};
        case Access::Sampled:
            return {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, in_shader,
                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
        case Access::StorageRead:
            return {VK_IMAGE_LAYOUT_GENERAL, in_shader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
        case Access::StorageWrite:
            return {VK_IMAGE_LAYOUT_GENERAL, in_shader, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
        case Access::StorageReadWrite:
            return {VK_IMAGE_LAYOUT_GENERAL, in_shader,
                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
        case Access::UniformRead:
            return {VK_IMAGE_LAYOUT_UNDEFINED, in_shader, VK_ACCESS_2_UNIFORM_READ_BIT};
        case Access::VertexRead:
            return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
                    VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT};
        case Access::IndexRead:
            return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT,
                    VK_ACCESS_2_INDEX_READ_BIT};
        case Access::IndirectRead:
            return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                    VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT};
        case Access::TransferSrc:
            return {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_READ_BIT};
        case Access::TransferDst:
            return {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransfer | VK_PIPELINE_STAGE_2_CLEAR_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT};
        // The spec synchronises resolves in COLOR_ATTACHMENT_OUTPUT with colour attachment
        // accesses, "whether the attachments are color or depth/stencil attachments".
        case Access::ResolveDst:
            return {depth ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
                          : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
        // Seed 002: SHADER_READ_ONLY for colour, the read-only depth layout for depth (which
        // the depth test may use at the same time).
        case Access::InputAttachment:
            return {depth ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                          : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_INPUT_ATTACHMENT_READ_BIT};
    }
    return {};
}

bool is_write(Access access) {
    switch (access) {
        case Access::ColorAttachment:
        case Access::DepthAttachment:
        case Access::StorageWrite:
        case Access::StorageReadWrite:
        case Access::TransferDst:
        case Access::ResolveDst:
            return true;
        default:
            return false;
    }
}

bool is_buffer_only(Access access) {
    return access == Access::UniformRead || access == Access::VertexRead ||
           access == Access::IndexRead || access == Access::IndirectRead;
}

bool is_image_only(Access access) {
    return access == Access::ColorAttachment || access == Access::DepthAttachment ||
           access == Access::DepthReadOnly || access == Access::Sampled ||
           access == Access::ResolveDst || access == Access::InputAttachment;
}

VkAccessFlags2 write_bits(VkAccessFlags2 access) {
    constexpr VkAccessFlags2 kWrites =
        VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
        VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
    return access & kWrites;
}

VkImageUsageFlags image_usage(Access access, bool depth) {
    switch (access) {
        case Access::ColorAttachment:
            return VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
        case Access::DepthAttachment:
        case Access::DepthReadOnly:
            return VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
        case Access::Sampled:
            return VK_IMAGE_USAGE_SAMPLED_BIT;
        case Access::StorageRead:
        case Access::StorageWrite:
        case Access::StorageReadWrite:
            return VK_IMAGE_USAGE_STORAGE_BIT;
        case Access::TransferSrc:
            return VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        case Access::TransferDst:
            return VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        case Access::ResolveDst:
            return depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT
                         : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
        case Access::InputAttachment:
            return VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT;
        default:
            return 0;
    }
}

VkBufferUsageFlags buffer_usage(Access access) {
    switch (access) {
        case Access::StorageRead:
        case Access::StorageWrite:
        case Access::StorageReadWrite:
            return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        case Access::UniformRead:
            return VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
        case Access::VertexRead:
            return VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
        case Access::IndexRead:
            return VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
        case Access::IndirectRead:
            return VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
        case Access::TransferSrc:
            return VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
        case Access::TransferDst:
            return VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        default:
            return 0;
    }
}

const char* access_name(Access access) {
    switch (access) {
        case Access::ColorAttachment:
            return "colour attachment";
        case Access::DepthAttachment:
            return "depth attachment";
        case Access::DepthReadOnly:
            return "depth read-only";
        case Access::Sampled:
            return "sampled";
        case Access::StorageRead:
            return "storage read";
        case Access::StorageWrite:
            return "storage write";
        case Access::StorageReadWrite:
            return "storage read-write";
        case Access::UniformRead:
            return "uniform";
        case Access::VertexRead:
            return "vertex input";
        case Access::IndexRead:
            return "index input";
        case Access::IndirectRead:
            return "indirect arguments";
        case Access::TransferSrc:
            return "transfer src";
        case Access::TransferDst:
            return "transfer dst";
        case Access::ResolveDst:
            return "resolve dst";
        case Access::InputAttachment:
            return "input attachment";
    }
    return "?";
}

const char* shader_name(Shader shader) {
    static constexpr const char* kNames[8] = {
        "default", "vertex",         "fragment",         "vertex+fragment",
        "compute", "vertex+compute", "fragment+compute", "vertex+fragment+compute"};
    return kNames[uint8_t(shader) & 7u];
}

}  // namespace ds::graph
