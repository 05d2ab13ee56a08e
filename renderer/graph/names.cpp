#include "renderer/graph/names.h"

#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <utility>

namespace ds::graph {
namespace {

using Bit = std::pair<uint64_t, const char*>;

// "A|B|C" for the known bits of `flags`, then any unknown rest in hex.
std::string bit_names(uint64_t flags, std::initializer_list<Bit> bits) {
    if (flags == 0) return "NONE";
    std::string out;
    for (const auto& [bit, name] : bits) {
        if ((flags & bit) != bit) continue;
        out += (out.empty() ? "" : "|") + std::string(name);
        flags &= ~bit;
    }
    if (flags) {
        char hex[32];
        std::snprintf(hex, sizeof hex, "0x%llx", static_cast<unsigned long long>(flags));
        out += (out.empty() ? "" : "|") + std::string(hex);
    }
    return out;
}

}  // namespace

const char* layout_name(VkImageLayout layout) {
    switch (layout) {
        case VK_IMAGE_LAYOUT_UNDEFINED:
            return "UNDEFINED";
        case VK_IMAGE_LAYOUT_GENERAL:
            return "GENERAL";
        case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
            return "COLOR_ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
            return "DEPTH_STENCIL_ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
            return "DEPTH_STENCIL_READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
            return "SHADER_READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
            return "TRANSFER_SRC_OPTIMAL";
        case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
            return "TRANSFER_DST_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL:
            return "DEPTH_ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL:
            return "DEPTH_READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL:
            return "READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL:
            return "ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_PRESENT_SRC_KHR:
            return "PRESENT_SRC_KHR";
        default:
            return "other layout";
    }
}

std::string stage_names(VkPipelineStageFlags2 stages) {
    return bit_names(stages,
                     {{VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, "TOP_OF_PIPE"},
                      {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, "DRAW_INDIRECT"},
                      {VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT, "INDEX_INPUT"},
                      {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, "VERTEX_ATTRIBUTE_INPUT"},
                      {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, "VERTEX_SHADER"},
                      {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT, "EARLY_FRAGMENT_TESTS"},
                      {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, "FRAGMENT_SHADER"},
                      {VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, "LATE_FRAGMENT_TESTS"},
                      {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, "COLOR_ATTACHMENT_OUTPUT"},
                      {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, "COMPUTE_SHADER"},
                      {VK_PIPELINE_STAGE_2_COPY_BIT, "COPY"},
                      {VK_PIPELINE_STAGE_2_BLIT_BIT, "BLIT"},
                      {VK_PIPELINE_STAGE_2_RESOLVE_BIT, "RESOLVE"},
                      {VK_PIPELINE_STAGE_2_CLEAR_BIT, "CLEAR"},
                      {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, "ALL_TRANSFER"},
                      {VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, "BOTTOM_OF_PIPE"},
                      {VK_PIPELINE_STAGE_2_HOST_BIT, "HOST"},
                      {VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT, "ALL_GRAPHICS"},
                      {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, "ALL_COMMANDS"}});
}

std::string access_names(VkAccessFlags2 access) {
    return bit_names(
        access, {{VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT, "INDIRECT_COMMAND_READ"},
                 {VK_ACCESS_2_INDEX_READ_BIT, "INDEX_READ"},
                 {VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT, "VERTEX_ATTRIBUTE_READ"},
                 {VK_ACCESS_2_UNIFORM_READ_BIT, "UNIFORM_READ"},
                 {VK_ACCESS_2_SHADER_READ_BIT, "SHADER_READ"},
                 {VK_ACCESS_2_SHADER_WRITE_BIT, "SHADER_WRITE"},
                 {VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT, "COLOR_ATTACHMENT_READ"},
                 {VK_ACCESS_2_INPUT_ATTACHMENT_READ_BIT, "INPUT_ATTACHMENT_READ"},
                 {VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, "COLOR_ATTACHMENT_WRITE"},
                 {VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT, "DEPTH_STENCIL_ATTACHMENT_READ"},
                 {VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, "DEPTH_STENCIL_ATTACHMENT_WRITE"},
                 {VK_ACCESS_2_TRANSFER_READ_BIT, "TRANSFER_READ"},
                 {VK_ACCESS_2_TRANSFER_WRITE_BIT, "TRANSFER_WRITE"},
                 {VK_ACCESS_2_HOST_READ_BIT, "HOST_READ"},
                 {VK_ACCESS_2_HOST_WRITE_BIT, "HOST_WRITE"},
                 {VK_ACCESS_2_MEMORY_READ_BIT, "MEMORY_READ"},
                 {VK_ACCESS_2_MEMORY_WRITE_BIT, "MEMORY_WRITE"},
                 {VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, "SHADER_SAMPLED_READ"},
                 {VK_ACCESS_2_SHADER_STORAGE_READ_BIT, "SHADER_STORAGE_READ"},
                 {VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, "SHADER_STORAGE_WRITE"}});
}

std::string image_usage_names(VkImageUsageFlags usage) {
    return bit_names(usage,
                     {{VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "TRANSFER_SRC"},
                      {VK_IMAGE_USAGE_TRANSFER_DST_BIT, "TRANSFER_DST"},
                      {VK_IMAGE_USAGE_SAMPLED_BIT, "SAMPLED"},
                      {VK_IMAGE_USAGE_STORAGE_BIT, "STORAGE"},
                      {VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, "COLOR_ATTACHMENT"},
                      {VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "DEPTH_STENCIL_ATTACHMENT"},
                      {VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT, "TRANSIENT_ATTACHMENT"},
                      {VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT, "INPUT_ATTACHMENT"}});
}

std::string buffer_usage_names(VkBufferUsageFlags usage) {
    return bit_names(usage, {{VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "TRANSFER_SRC"},
                             {VK_BUFFER_USAGE_TRANSFER_DST_BIT, "TRANSFER_DST"},
                             {VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "UNIFORM"},
                             {VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "STORAGE"},
                             {VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "INDEX"},
                             {VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "VERTEX"},
                             {VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "INDIRECT"}});
}

const char* semantic_name(Semantic semantic) {
    switch (semantic) {
        case Semantic::ReverseZDepth:
            return "ReverseZDepth";
        case Semantic::ForwardZDepth:
            return "ForwardZDepth";
        case Semantic::ShadowDepth:
            return "ShadowDepth";
        case Semantic::EncodedNormal:
            return "EncodedNormal";
        case Semantic::UnormScalar:
            return "UnormScalar";
        case Semantic::AO:
            return "AO";
        case Semantic::HdrColor:
            return "HdrColor";
        case Semantic::LdrColor:
            return "LdrColor";
        case Semantic::Count:
            return "Count";
        case Semantic::SurfaceId:
            return "SurfaceId";
        case Semantic::DepthStep:
            return "DepthStep";
        case Semantic::Other:
            return "Other";
        case Semantic::Scalar:
            return "Scalar";
    }
    return "?";
}

const char* lifetime_name(Lifetime lifetime) {
    switch (lifetime) {
        case Lifetime::Transient:
            return "transient";
        case Lifetime::History:
            return "history";
        case Lifetime::External:
            return "external";
    }
    return "?";
}

}  // namespace ds::graph
