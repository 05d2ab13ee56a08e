#pragma once
// Readable names of the Vulkan enums and flags a graph dump prints (formats: format::name in
// renderer/format). Vulkan's own string helper header is not packaged in Debian 12, and the
// dump must read the same everywhere.
#include <string>

#include <vulkan/vulkan.h>

#include "renderer/graph/types.h"

namespace ds::graph {

const char* layout_name(VkImageLayout layout);          // "COLOR_ATTACHMENT_OPTIMAL"
std::string stage_names(VkPipelineStageFlags2 stages);  // "EARLY_FRAGMENT_TESTS|..."; "NONE"
std::string access_names(VkAccessFlags2 access);        // "SHADER_SAMPLED_READ|..."; "NONE"
std::string image_usage_names(VkImageUsageFlags usage);
std::string buffer_usage_names(VkBufferUsageFlags usage);
const char* semantic_name(Semantic semantic);  // "ReverseZDepth", ...
const char* lifetime_name(Lifetime lifetime);  // "transient", "history", "external"

}  // namespace ds::graph
