#pragma once
// The frames the Vulkan layer saw (its frames.jsonl: one JSON object per frame, layer/frames.h)
// and `depthscope layer --list`'s lines for them.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ds::capture {

struct LayerPass {
    bool dynamic = false;
    uint32_t subpass = 0;
    std::string label;
    uint32_t width = 0, height = 0;
    int depth_format = 0;  // VkFormat; 0: no depth attachment
    uint32_t samples = 1;
    uint32_t draws = 0;
    bool operator==(const LayerPass&) const = default;
};

struct LayerFrame {
    uint64_t number = 0;
    bool by_present = true;  // false: delimited by submissions with a depth pass
    bool presented = true;   // false: the application ended before presenting it
    uint32_t submissions = 0;
    std::vector<LayerPass> passes;
};

// Throws ds::Error for a malformed file; a missing file is no frames.
std::vector<LayerFrame> read_layer_frames(const std::filesystem::path& file);

// One line per run of frames with the same passes, then one line per pass of it.
std::vector<std::string> list_lines(const std::vector<LayerFrame>& frames);

}  // namespace ds::capture
