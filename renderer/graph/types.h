#pragma once
// Render graph vocabulary: typed handles, resource descriptions and the semantic every image
// carries (DESIGN decision 7). No Vulkan calls: only Vulkan's enums and flag types.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include <vulkan/vulkan.h>

#include "renderer/graph/display.h"
#include "renderer/graph/semantic.h"
#include "renderer/vk/memory.h"

namespace ds::graph {

inline constexpr uint32_t kNoResource = UINT32_MAX;

// Indices into the frame's resource table; the two types keep images and buffers apart.
struct ImageHandle {
    uint32_t index = kNoResource;
    bool valid() const { return index != kNoResource; }
    bool operator==(const ImageHandle&) const = default;
};
struct BufferHandle {
    uint32_t index = kNoResource;
    bool valid() const { return index != kNoResource; }
    bool operator==(const BufferHandle&) const = default;
};

// Either relative to the graph's output size (recreated when that changes) or absolute.
struct ImageSize {
    float scale = 1.0f;
    VkExtent2D absolute{0, 0};

    static ImageSize relative(float scale) { return {scale, {0, 0}}; }
    static ImageSize fixed(uint32_t width, uint32_t height) { return {1.0f, {width, height}}; }
    bool is_relative() const { return absolute.width == 0 || absolute.height == 0; }
    VkExtent2D resolve(VkExtent2D output) const;  // never smaller than 1x1
};

// Name `.size` in designated initializers: GCC 12 warns (-Wmissing-field-initializers) when a
// member of class type is left out.
struct ImageDesc {
    VkFormat format = VK_FORMAT_UNDEFINED;
    ImageSize size;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    uint32_t mip_levels = 1;
    Semantic semantic = Semantic::Other;
    Display display{};  // how a Scalar image is shown; the other semantics ignore it
};

struct BufferDesc {
    VkDeviceSize size = 0;
    vk::MemoryUsage memory = vk::MemoryUsage::GpuOnly;
};

// What a user outside the graph did last (initial) or does next (final) with an imported
// resource: the other half of the barrier the graph records.
struct ExternalState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // images; UNDEFINED as final: keep
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;

    // A swapchain image: presentation waits on a semaphore, so no stage is needed.
    static ExternalState present() { return {VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, 0, 0}; }
    // An image the caller copies out after the graph (readback, capture).
    static ExternalState transfer_src() {
        return {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                VK_ACCESS_2_TRANSFER_READ_BIT};
    }
    // A host-visible buffer the CPU reads after the frame's fence.
    static ExternalState host_read() {
        return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT};
    }
};

struct ExternalImage {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    ImageDesc desc;  // desc.size must be fixed(): the graph does not own (or resize) it
    ExternalState initial;
    std::optional<ExternalState> final;  // none: left as the last pass used it
    // What renderings attach, where it is not `view` (both aspects of a depth/stencil format).
    VkImageView attachment_view = VK_NULL_HANDLE;
};

struct ExternalBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    ExternalState initial;
    std::optional<ExternalState> final;
};

enum class Lifetime : uint8_t {
    Transient,  // graph-owned, contents discarded at the start of every frame
    History,    // graph-owned pair, contents kept for the next frame (temporal passes)
    External,   // imported by the caller, with initial and final states
};

// Graphics passes draw (attachments allowed); compute passes dispatch; transfer passes copy,
// clear and fill (no shader stage of their own).
enum class PassKind : uint8_t { Graphics, Compute, Transfer };

// What a pass is for, so a report or a panel can group and fold: the frame's own work,
// clearing what a later pass accumulates into, reading results back to the host, work a
// diagnostic adds beside a frame pass (Measure: count_fragments' rasterized counts), or a pixel
// history replay (History: a geometry pass's draws again, instrumented, before the pass itself).
enum class PassRole : uint8_t { Frame, Clear, ReadBack, Measure, History };

// What a graphics pass declares about an attachment it renders to (PassBuilder::color /
// depth). Keep: the contents where there are any (written earlier this frame, or an import or
// history that arrives with them), else nothing to load; Clear: the declared value; DontCare:
// the pass covers every pixel. Store ops are the graph's: STORE where a later pass or the
// frame's end still needs the contents, DONT_CARE where nothing does, NONE for a read-only
// depth (a test that writes nothing).
enum class Load : uint8_t { Keep, Clear, DontCare };

struct ColorUse {
    Load load = Load::Keep;
    VkClearColorValue clear{};  // Load::Clear
};

struct DepthUse {
    Load load = Load::Keep;
    float clear = 0.0f;      // Load::Clear
    bool read_only = false;  // tested, never written (a read-only layout)
};

// A pass's identity in the graph: its name, what it runs, and what it is for.
struct PassDecl {
    std::string name;
    PassKind kind = PassKind::Graphics;
    PassRole role = PassRole::Frame;
    PassDecl(std::string n, PassKind k = PassKind::Graphics, PassRole r = PassRole::Frame)
        : name(std::move(n)), kind(k), role(r) {}
    PassDecl(const char* n, PassKind k = PassKind::Graphics, PassRole r = PassRole::Frame)
        : name(n), kind(k), role(r) {}
};

const char* pass_kind_name(PassKind kind);  // "graphics" | "compute" | "transfer"
// "frame" | "clear" | "readback" | "measure" | "history"
const char* pass_role_name(PassRole role);

}  // namespace ds::graph
