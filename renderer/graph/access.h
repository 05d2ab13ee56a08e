#pragma once
// Access kinds a pass declares, and what each means for Vulkan: image layout, pipeline stages,
// access mask, usage flag. One table (access.cpp) so every barrier is as precise as its kind.
#include <cstdint>

#include <vulkan/vulkan.h>

namespace ds::graph {

enum class Access : uint8_t {
    ColorAttachment,   // rendered to (LOAD and blending read it too)
    DepthAttachment,   // depth test and depth writes
    DepthReadOnly,     // depth test without writes; may be sampled in the same pass
    Sampled,           // texture reads
    StorageRead,       // images and buffers
    StorageWrite,      // images and buffers
    StorageReadWrite,  // images and buffers (atomics, read-modify-write)
    UniformRead,       // buffers
    VertexRead,        // buffers: vertex input
    IndexRead,         // buffers: index input
    IndirectRead,      // buffers: indirect draw / dispatch arguments
    TransferSrc,       // copy, blit, resolve source
    TransferDst,       // copy, blit, resolve, clear destination
    ResolveDst,        // resolve attachment of dynamic rendering (colour or depth)
    // Read at the fragment's own pixel (subpassLoad) in a later subpass of a subpass group:
    // from tile memory on a tiler. Only inside a group (graph/subpass.h).
    InputAttachment,
};

// Shader stages of a Sampled / Storage / Uniform access; a bit set. Default resolves to the
// pass kind's stage: fragment for graphics passes, compute for compute passes.
enum class Shader : uint8_t { Default = 0, Vertex = 1, Fragment = 2, Compute = 4 };
constexpr Shader operator|(Shader a, Shader b) {
    return Shader(uint8_t(a) | uint8_t(b));
}
constexpr bool has(Shader set, Shader bit) {
    return (uint8_t(set) & uint8_t(bit)) != 0;
}

// An access as the barrier computation sees it. `access` holds every bit (the destination
// side of a barrier); its write bits alone are the source side of the next one.
struct Use {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // images only
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

// `depth` is whether the image has a depth/stencil format (resolve destinations differ).
Use describe(Access access, Shader shader, bool depth);

bool is_write(Access access);        // true for kinds that may modify contents
bool is_buffer_only(Access access);  // Uniform/Vertex/Index/Indirect: never on an image
bool is_image_only(Access access);   // attachments, Sampled, ResolveDst
VkAccessFlags2 write_bits(VkAccessFlags2 access);

VkImageUsageFlags image_usage(Access access, bool depth);
VkBufferUsageFlags buffer_usage(Access access);

const char* access_name(Access access);  // "colour attachment", "sampled", ...
const char* shader_name(Shader shader);  // "fragment", "vertex+fragment", ...

}  // namespace ds::graph
