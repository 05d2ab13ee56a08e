#pragma once
// Seed 002's questions about one subpass group, asked of the planned render pass: does the
// colour a tile holds fit 128 (or 256) bits per pixel, and would a tiler merge the subpasses?
// Pure (no Vulkan calls), like subpass.h: a test gives it a plan, the report and the Tiler
// panel show what it says.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "renderer/graph/subpass.h"

namespace ds::graph {

struct TilerAttachment {
    std::string name;
    std::string format;
    std::string role;   // "colour", "depth", "resolve" ("+input" where a subpass reads it)
    uint32_t bits = 0;  // per texel (per sample)
    uint32_t samples = 1;
    std::string load, store;
    bool transient = false;         // tile memory only (TRANSIENT_ATTACHMENT)
    bool lazily_allocated = false;  // its memory is LAZILY_ALLOCATED
};

// One of seed 002's merge conditions, checked.
struct TilerCondition {
    std::string name;
    bool ok = false;
    std::string detail;
};

struct TilerReport {
    std::string group;
    uint32_t subpasses = 0;
    std::vector<TilerAttachment> attachments;
    // The colour attachments a tile holds (colour and input; not depth, not resolve
    // destinations, which go to memory): bits per sample, and for every sample of a pixel.
    uint32_t bits_per_pixel = 0;
    uint32_t samples = 1;
    uint32_t tile_bits_per_pixel = 0;
    bool fits_128 = false, fits_256 = false;
    std::vector<TilerCondition> conditions;
    bool mergeable = false;
    std::string verdict;  // "a tiler can merge these subpasses: yes" / "no (why)"
};

// `lazily_allocated` per group attachment (the graph knows which images got such memory).
TilerReport tiler_report(const GroupPlan& group, std::span<const ResourceInfo> resources,
                         std::span<const bool> lazily_allocated);

}  // namespace ds::graph
