#pragma once
// What the layer's Z-fight and EQUAL checks (settings zfight, equal_check) make of a depth
// pass's records (issue 29). Pure C++, no Vulkan calls.
//
// After a pass with depth-writing draws, the layer draws them twice more in an attachment-less
// render pass of its own with their fragment shaders rewritten (layer/spirv/survival.h): the
// first re-draw keeps, per pixel, the nearest depth any surviving (not discarded) fragment
// reaches; the second appends a record for every surviving fragment within zfight_steps depth
// steps of it: (pixel, draw, instance, depth). From the records, in draw order and with each
// draw's depth compare op, analyse_depth_pass() finds the pixel's winner (the fragment whose
// depth the attachment keeps) and its competitors: other (draw, instance)s within zfight_steps
// steps of the winner, in the attachment format's steps (D32: ULPs of the float; D24 / D16:
// unorm steps), as depthscope's own zfight does.
#include <cstdint>
#include <map>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "layer/commands.h"

namespace ds::layer {

// A draw's geometry: what the EQUAL check compares between a prepass draw and a later one.
struct DrawGeometry {
    bool indexed = false;
    VkBuffer index_buffer = VK_NULL_HANDLE;
    VkDeviceSize index_offset = 0;
    VkIndexType index_type = VK_INDEX_TYPE_UINT32;
    std::map<uint32_t, std::pair<VkBuffer, VkDeviceSize>> vertex;  // the pipeline's bindings
    DrawArgs args{};
};
// The same index or vertex range (instances may be grouped differently), index buffer, and the
// same buffer and offset at every vertex binding both pipelines read.
bool same_geometry(const DrawGeometry& a, const DrawGeometry& b);

// How a draw tests and writes depth (static or dynamic state as it was at the draw).
struct DepthUse {
    bool test = false, write = false;
    VkCompareOp op = VK_COMPARE_OP_ALWAYS;
    bool writes() const { return test && write; }
    // Tested EQUAL, or LESS_OR_EQUAL / GREATER_OR_EQUAL without writing: the forward pass
    // of a depth prepass.
    bool equal_like() const;
    // Nearer is the smaller depth (LESS, LESS_OR_EQUAL) or the larger (GREATER...).
    bool reverse() const { return op == VK_COMPARE_OP_GREATER || op == VK_COMPARE_OP_GREATER_OR_EQUAL; }
};

// One record as the survival shader appends it (4 words).
struct DepthRecord {
    uint32_t pixel, draw, instance, depth;  // depth: the float's bits
};

// A depth value in the attachment's steps: D32 the float's bits, D24 / D16 unorm levels.
uint32_t depth_steps_value(uint32_t depth_bits, uint32_t float_bits);
uint32_t depth_bits_of(VkFormat format);  // 32, 24 or 16 (0: not a depth format)

struct DrawInstance {
    uint32_t draw = 0, instance = 0;  // draw: index in the frame's draws
    auto operator<=>(const DrawInstance&) const = default;
};

struct DepthPair {
    DrawInstance a, b;  // a < b
    uint64_t pixels = 0;
    uint32_t min_steps = 0;
};

struct DepthPassAnalysis {
    uint32_t width = 0, height = 0;
    std::vector<DepthPair> pairs;           // most pixels first
    uint64_t pixels = 0;                    // pixels with a competitor
    std::vector<uint32_t> competitors;      // per pixel: competing (draw, instance)s
    std::vector<DrawInstance> winners;      // per pixel (draw UINT32_MAX: none)
    uint64_t records = 0, dropped = 0;      // appended, and lost past the buffer
};

// `records`: the pass's records (any order); `uses`: each draw's DepthUse by frame draw index
// (the records' draw ids already mapped to it); `first_draw`..: draws are in frame order.
DepthPassAnalysis analyse_depth_pass(std::span<const DepthRecord> records, uint32_t width,
                                     uint32_t height, uint32_t depth_bits, uint32_t max_steps,
                                     const std::map<uint32_t, DepthUse>& uses);

// The EQUAL check of one pass: per pixel, the survivors of its EQUAL re-draws (`equal`, from
// the pass's depth words) against the winners of the earlier pass it draws again: a hole where
// a prepass draw whose geometry the pass draws again won and nothing survived, a tie where
// more than one fragment survived.
struct EqualCheckResult {
    uint32_t prepass = 0;  // the frame pass
    uint64_t holes = 0, multiple = 0;
    std::vector<uint32_t> marks;  // per pixel: 0 ok, 1 hole, 2 tie (depthscope's own codes)
    std::map<DrawInstance, std::pair<uint64_t, uint64_t>> by_winner;  // holes, multiple
};
struct PrepassWinners {
    uint32_t pass = 0, width = 0, height = 0;
    std::vector<DrawInstance> winners;
};
// `words`: 2 per pixel of width x height, the second the survivors.
EqualCheckResult equal_check(const uint32_t* words, uint32_t width, uint32_t height,
                             const PrepassWinners& prepass, const std::set<uint32_t>& matched);

}  // namespace ds::layer
